// description() and from_string() of every schema type, generated: each is the generic text
// codec applied to that type.
#include "ringlet/whiteboard/messages.hpp"

#include "ringlet/whiteboard/text_format.hpp"

namespace ringlet::wb {

#define WB_MESSAGE_BEGIN(Name, Id, Version)                                                    \
  std::string Name::description() const { return detail::describe_message(*this); }          \
  Result<Name> Name::from_string(std::string_view text) {                                      \
    return detail::parse_message<Name>(text);                                                  \
  }
#include "ringlet/whiteboard/schema.def"

}  // namespace ringlet::wb
