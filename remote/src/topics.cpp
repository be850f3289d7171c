#include "ringlet/remote/topics.hpp"

#include <cctype>

namespace ringlet::remote {

std::string topic_name(std::string_view type_name) {
  std::string out = "rt/ringlet/";
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

}  // namespace ringlet::remote
