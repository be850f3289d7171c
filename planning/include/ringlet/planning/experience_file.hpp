#pragma once
// Experiences on disk: a text file, one experience a line, so that it can be read by a person, by
// Python and by Weka's CSV loader (after swapping the separator) as well as here.
//
//   ringlet-experiences 1
//   frame time_ns duration_s commanded_speed achieved_speed diagonal from to ... corner_right
//   812 8120000000 0.93 2 1.61 0 0 0.015625 ...
//
// Line 1 names the format and its version; line 2 the columns, which must be exactly this
// version's (a file written with other features is refused, never misread). Numbers are written
// in the shortest form that reads back to the same double (std::to_chars), so a save and a load
// give bit-identical experiences.
#include <filesystem>
#include <span>
#include <stdexcept>
#include <vector>

#include "ringlet/planning/experience.hpp"

namespace ringlet::planning {

inline constexpr int kExperienceFileVersion = 1;

/// A file that cannot be read or written; the message names the file and, for bad content, the
/// line ("path:line: what").
class ExperienceFileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Writes `experiences` to `path`, replacing it whole: the data goes to a temporary file beside it
/// that is renamed over `path` only once complete, so a reader never sees half a file.
void save_experiences(const std::filesystem::path& path, std::span<const Experience> experiences);

/// Every experience in `path`, in file order; throws ExperienceFileError on the first bad line
/// (nothing is returned then: no half-loaded set).
[[nodiscard]] std::vector<Experience> load_experiences(const std::filesystem::path& path);

}  // namespace ringlet::planning
