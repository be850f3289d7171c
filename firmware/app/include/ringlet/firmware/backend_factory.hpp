#pragma once
// The one place in firmware/ that knows the robot backends: it reads each backend's own
// configuration section ([sim], ...) and builds the robot by name. Everything else in the firmware
// sees only hal::Robot, hal::Camera and hal::GroundTruth. The OpenCV camera is not linked here: a
// program that offers it passes its maker in (firmware/camera_opencv), so that only that program
// loads OpenCV.
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "ringlet/firmware/config.hpp"
#include "ringlet/hal/clock.hpp"
#include "ringlet/hal/robot.hpp"
#include "ringlet/planning/movingai.hpp"

namespace ringlet::hal::can {
struct CanSettings;
}  // namespace ringlet::hal::can

namespace ringlet::firmware {

class Section;

/// The backends this build can drive (robot.backend's values); each has a section of its name.
[[nodiscard]] const std::vector<std::string>& backend_names();

/// Reads the section of backend `name` (an absent section is empty: its defaults). `so_far` is the
/// configuration read before it. ConfigError "file:line:col: key: message" on problems.
[[nodiscard]] std::shared_ptr<const BackendSettings> read_backend_settings(const std::string& name, Section& section,
                                                                           const std::filesystem::path& base_dir,
                                                                           const FirmwareConfig& so_far);

/// The robot of config.backend. Loads what the backend needs (the world file of "sim"): bad input
/// is a ConfigError naming the file and the key that named it.
[[nodiscard]] std::unique_ptr<hal::Robot> make_robot(const FirmwareConfig& config);

/// The [can] section as read, the settings the "can" backend drives its board with; null unless
/// robot.backend is "can".
[[nodiscard]] const hal::can::CanSettings* can_settings(const FirmwareConfig& config) noexcept;

/// The "sim" backend's world as the planner's prior map ([planner] prior_map): the configuration's
/// planner grid, first row the north edge as a .map file reads, a cell blocked ('@') where an
/// obstacle or the world's edge comes within half a cell of its centre. A ConfigError naming
/// robot.backend when it is not "sim"; the world's errors name its file:line.
[[nodiscard]] planning::MovingAiMap sim_world_map(const FirmwareConfig& config);

/// Makes the camera of [camera] backend "opencv" (ringlet::firmware::make_opencv_camera).
using OpenCvCameraMaker = std::unique_ptr<hal::Camera> (*)(const FirmwareConfig& config, const hal::Clock& clock);

/// The camera [camera] asks for when it is not the robot's own (backend "opencv", made by
/// `opencv_camera`), else null. A ConfigError naming camera.backend's file:line:col when the
/// configuration asks for the OpenCV camera and the program passed no maker.
[[nodiscard]] std::unique_ptr<hal::Camera> make_camera(const FirmwareConfig& config, const hal::Clock& clock,
                                                       OpenCvCameraMaker opencv_camera);

}  // namespace ringlet::firmware
