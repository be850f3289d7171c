// ringlet-can-spec: the board's CAN protocol (hal/can/protocol.hpp) as a DBC file, for standard
// CAN tools (cantools, SavvyCAN, Vector's), or as the Markdown table of hal/can/README.md.
//   ringlet-can-spec --dbc > hal/can/ringlet_board.dbc
//   ringlet-can-spec --markdown
// Exit codes: 0 written, 2 bad flags.
#include <CLI/CLI.hpp>

#include <iostream>

#include "ringlet/hal/can/protocol.hpp"

int main(int argc, char** argv) {
  CLI::App app{"ringlet-can-spec: the board's CAN protocol as a DBC file or a Markdown table. Exit codes: 0 written, 2 bad flags."};
  bool dbc = false, markdown = false;
  auto* d = app.add_flag("--dbc", dbc, "the DBC file (hal/can/ringlet_board.dbc)");
  app.add_flag("--markdown", markdown, "the table of hal/can/README.md")->excludes(d);
  try {
    app.parse(argc, argv);
    if (!dbc && !markdown) throw CLI::RequiredError("--dbc or --markdown");
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 2;
  }
  std::cout << (dbc ? ringlet::hal::can::dbc_text() : ringlet::hal::can::markdown_table());
  return 0;
}
