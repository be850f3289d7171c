// ringlet-world-map: the map a robot is given before it drives ([planner] prior_map), made from a
// configuration's simulated world on the configuration's planner grid (firmware::sim_world_map).
// Powers & Balch's planner knew the obstacles of its test worlds ("obstacles in the map are shown
// in black", Fig. 3); this gives our planner the same start. A cell is blocked when an obstacle
// (or the world's edge) comes within half a cell of its centre, the footprint the laser would mark
// over time.
//
//   ringlet-world-map --config firmware/config/pb_woods.toml -o woods.map
//
// Exit codes: 0 written, 2 bad input (flags, configuration, world, output).
#include <CLI/CLI.hpp>

#include <fstream>
#include <iostream>
#include <string>

#include "ringlet/firmware/backend_factory.hpp"
#include "ringlet/firmware/config.hpp"
#include "ringlet/planning/movingai.hpp"

int main(int argc, char** argv) {
  CLI::App app{"ringlet-world-map: the prior map ([planner] prior_map, MovingAI .map) of a configuration's\n"
               "simulated world on its planner grid"};
  std::string config_path, out_path;
  app.add_option("-c,--config", config_path, "firmware configuration (TOML) with [sim] world and [planner]")
      ->required()
      ->check(CLI::ExistingFile);
  app.add_option("-o,--output", out_path, "the .map file to write (default: standard output)");
  CLI11_PARSE(app, argc, argv);

  try {
    const ringlet::firmware::FirmwareConfig config = ringlet::firmware::load_config(config_path);
    const ringlet::planning::MovingAiMap m = ringlet::firmware::sim_world_map(config);
    std::size_t blocked = 0;
    for (const char c : m.terrain) blocked += c == '@' ? 1U : 0U;
    if (out_path.empty()) {
      ringlet::planning::write_movingai_map(std::cout, m);
    } else {
      std::ofstream out(out_path, std::ios::binary | std::ios::trunc);
      if (out) ringlet::planning::write_movingai_map(out, m);
      if (!out.flush()) {
        std::cerr << "ringlet-world-map: --output " << out_path << ": cannot write the map\n";
        return 2;
      }
    }
    std::cerr << "ringlet-world-map: " << config.backend_settings->source_name() << ": " << blocked << " of " << m.terrain.size()
              << " cells blocked (" << m.width << " x " << m.height << ", " << config.planner.map.resolution << " m)"
              << (out_path.empty() ? "" : " -> " + out_path) << '\n';
    return 0;
  } catch (const std::exception& e) {  // ConfigError, WorldError: they name file:line
    std::cerr << "ringlet-world-map: " << e.what() << '\n';
    return 2;
  }
}
