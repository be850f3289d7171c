#include "ringlet/remote/topics.hpp"

#include <cctype>

namespace ringlet::remote {

namespace {
std::string snake(std::string out, std::string_view type_name) {
  for (std::size_t i = 0; i < type_name.size(); ++i) {
    const auto c = static_cast<unsigned char>(type_name[i]);
    if (std::isupper(c) != 0) {
      if (i > 0) out.push_back('_');
      out.push_back(static_cast<char>(std::tolower(c)));
    } else {
      out.push_back(static_cast<char>(c));
    }
  }
  return out;
}
}  // namespace

std::string topic_name(std::string_view type_name) { return snake("rt/ringlet/", type_name); }
std::string request_topic_name(std::string_view type_name) { return snake("rt/ringlet/request/", type_name); }

}  // namespace ringlet::remote
