// ringlet-vision-calibrate: builds the colour table (LUT) the vision pipeline classifies with, the
// job Mi-Pal's Vladcal did: from YUV threshold boxes (the defaults, any bound overridden by a flag
// such as --line-y-min), or from labelled example images (every *_labels.png in a folder with its
// picture, e.g. what ringlet-dataset writes); writes it with --out, and with --evaluate reports how
// a table (built here, or --lut) classifies a labelled set: the confusion matrix and per-class
// precision and recall, on the terminal and optionally as JSON.
//
// Exit codes: 0 done · 2 bad input (flags, missing or unreadable folder or image, bad labels,
// missing or corrupt --lut) · 1 internal or output error (cannot write --out or --json).
#include <CLI/CLI.hpp>

#include <array>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <string>
#include <unistd.h>

#include "auto_calibration.hpp"
#include "labelled_set.hpp"
#include "vision_io.hpp"

namespace {

using namespace ringlet::vision;
namespace tools = ringlet::vision::tools;

constexpr std::array<const char*, 3> kBoxNames{"ball", "line", "field"};
constexpr std::array<const char*, 6> kBoundNames{"y-min", "y-max", "u-min", "u-max", "v-min", "v-max"};

struct Options {
  bool thresholds = false;
  std::array<std::array<int, 6>, 3> bounds{};  // −1: keep the default
  std::string examples;
  std::string lut;
  std::string out;
  std::string evaluate;
  std::string json;
  int stride = 4;
  int bin_bits = ColourTable::kDefaultBinBits;
  std::string fill = "nearest";
  int max_fill_distance = ExampleTrainingOptions{}.max_fill_distance;
  bool quiet = false;
  bool auto_mode = false;
  std::vector<std::string> photos;
  std::string report;
  std::string classes_dir;
  tools::CameraOptions camera;
};

std::uint8_t* bound_field(YuvRange& r, std::size_t i) {
  std::array<std::uint8_t*, 6> f{&r.y_min, &r.y_max, &r.u_min, &r.u_max, &r.v_min, &r.v_max};
  return f[i];
}

ColourThresholds thresholds_from(const Options& o) {
  ColourThresholds t;
  std::array<YuvRange*, 3> boxes{&t.ball, &t.line, &t.field};
  for (std::size_t b = 0; b < boxes.size(); ++b) {
    for (std::size_t i = 0; i < kBoundNames.size(); ++i) {
      if (o.bounds[b][i] >= 0) *bound_field(*boxes[b], i) = static_cast<std::uint8_t>(o.bounds[b][i]);
    }
  }
  return t;
}

/// A progress line on stderr (rewritten in place on a terminal, every tenth otherwise).
std::function<void(std::size_t, std::size_t)> progress_printer(const Options& o, const char* what) {
  if (o.quiet) return {};
  return [what](std::size_t done, std::size_t total) {
    static const bool tty = isatty(fileno(stderr)) != 0;
    if (tty) {
      std::fprintf(stderr, "\rringlet-vision-calibrate: %s %zu/%zu images", what, done, total);
      if (done == total) std::fputc('\n', stderr);
    } else if (done == total || (total >= 10 && done % (total / 10) == 0)) {
      std::fprintf(stderr, "ringlet-vision-calibrate: %s %zu/%zu images\n", what, done, total);
    }
  };
}

void print_confusion(const Confusion& c, std::ostream& os) {
  char line[256];
  os << "confusion (rows: labelled as, columns: classified as), " << c.total() << " samples\n";
  std::snprintf(line, sizeof line, "%-8s %12s %12s %12s %12s %10s %10s\n", "", "other", "field", "line", "ball",
                "precision", "recall");
  os << line;
  for (int t = 0; t < kColourClassCount; ++t) {
    const auto& row = c.counts[static_cast<std::size_t>(t)];
    const auto cls = static_cast<ColourClass>(t);
    std::snprintf(line, sizeof line, "%-8s %12llu %12llu %12llu %12llu %9.2f%% %9.2f%%\n", to_string(cls),
                  static_cast<unsigned long long>(row[0]), static_cast<unsigned long long>(row[1]),
                  static_cast<unsigned long long>(row[2]), static_cast<unsigned long long>(row[3]),
                  100.0 * c.precision(cls), 100.0 * c.recall(cls));
    os << line;
  }
}

nlohmann::json confusion_json(const Confusion& c, const std::string& table, const std::string& set, std::size_t images) {
  nlohmann::json classes = nlohmann::json::object();
  nlohmann::json counts = nlohmann::json::array();
  for (int t = 0; t < kColourClassCount; ++t) {
    const auto cls = static_cast<ColourClass>(t);
    counts.push_back(c.counts[static_cast<std::size_t>(t)]);
    std::uint64_t labelled = 0;
    for (const std::uint64_t n : c.counts[static_cast<std::size_t>(t)]) labelled += n;
    classes[to_string(cls)] = {{"precision", c.precision(cls)}, {"recall", c.recall(cls)}, {"labelled", labelled}};
  }
  return {{"table", table}, {"labelled_set", set}, {"images", images}, {"samples", c.total()},
          {"class_order", {"other", "field", "line", "ball"}}, {"counts", counts}, {"classes", classes},
          {"note", "counts[labelled][classified]"}};
}

int run(const Options& o) {
  if (o.out.empty() && o.evaluate.empty()) {
    throw tools::ToolError("nothing to do: give --out FILE (write the table) and/or --evaluate DIR");
  }
  if (!o.lut.empty() && (!o.examples.empty() || o.thresholds)) {
    throw tools::ToolError("--lut evaluates an existing table; it does not go with --examples or --thresholds");
  }
  if (!o.examples.empty() && o.thresholds) throw tools::ToolError("--examples and --thresholds: choose one");
  if (o.auto_mode && (!o.examples.empty() || o.thresholds || !o.lut.empty())) {
    throw tools::ToolError("--auto builds the table from photos; it does not go with --examples, --thresholds or --lut");
  }
  if (!o.auto_mode && !o.photos.empty()) {
    throw tools::ToolError("photos given without --auto: " + o.photos.front() + " (--auto PHOTO... builds a table from them)");
  }
  if (!o.auto_mode && (!o.report.empty() || !o.classes_dir.empty())) {
    throw tools::ToolError("--report and --classes-dir go with --auto");
  }

  std::string source;
  ColourTable table;
  if (!o.lut.empty()) {
    table = tools::load_table(o.lut);
    source = o.lut;
  } else if (o.auto_mode) {
    tools::AutoOptions options;
    options.camera = o.camera;
    options.stride = o.stride;
    options.bin_bits = o.bin_bits;
    options.training.fill = o.fill == "other" ? EmptyBinFill::kOther : EmptyBinFill::kNearest;
    options.training.max_fill_distance = o.max_fill_distance;
    options.classes_dir = o.classes_dir;
    tools::AutoCalibration calibration = tools::auto_calibrate(o.photos, options);
    for (const auto& photo : calibration.photos) std::cout << tools::describe(photo) << "\n";
    if (!o.report.empty()) {
      std::ofstream file(o.report);
      file << tools::report_json(calibration).dump(2) << "\n";
      if (!file) {
        std::cerr << "ringlet-vision-calibrate: " << o.report << ": cannot write the report\n";
        return 1;
      }
    }
    table = std::move(calibration.table);
    source = "auto from " + std::to_string(o.photos.size()) + " photos";
  } else if (!o.examples.empty()) {
    const auto images = tools::find_labelled_images(o.examples);
    const auto samples = tools::sample_labelled_set(images, o.stride, progress_printer(o, "sampling"));
    ExampleTrainingOptions training;
    training.fill = o.fill == "other" ? EmptyBinFill::kOther : EmptyBinFill::kNearest;
    training.max_fill_distance = o.max_fill_distance;
    table = ColourTable::from_examples(samples, training, o.bin_bits);
    source = "examples " + o.examples;
    std::cerr << "ringlet-vision-calibrate: table from " << samples.size() << " samples of " << images.size()
              << " images in " << o.examples << "\n";
  } else {
    table = ColourTable::from_thresholds(thresholds_from(o), o.bin_bits);
    source = "thresholds";
  }

  if (!o.out.empty()) {
    const std::string error = table.save(o.out);
    if (!error.empty()) {
      std::cerr << "ringlet-vision-calibrate: " << error << "\n";
      return 1;
    }
    std::cout << "wrote colour table " << o.out << " (" << table.bin_bits() << " bits per channel, from " << source << ")\n";
  }

  if (!o.evaluate.empty()) {
    const auto images = tools::find_labelled_images(o.evaluate);
    const auto samples = tools::sample_labelled_set(images, o.stride, progress_printer(o, "evaluating"));
    const Confusion c = table.confusion(samples);
    std::cout << "table " << source << " on " << images.size() << " labelled images in " << o.evaluate
              << " (every " << o.stride << "th pixel)\n";
    print_confusion(c, std::cout);
    if (!o.json.empty()) {
      std::ofstream file(o.json);
      file << confusion_json(c, source, o.evaluate, images.size()).dump(2) << "\n";
      if (!file) {
        std::cerr << "ringlet-vision-calibrate: " << o.json << ": cannot write\n";
        return 1;
      }
    }
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  for (auto& box : o.bounds) box.fill(-1);
  CLI::App app{"ringlet-vision-calibrate: build the vision colour table (LUT) from YUV thresholds or labelled "
               "example images, write it, and evaluate a table on labelled images (confusion matrix). "
               "Exit codes: 0 done, 2 bad input, 1 internal or output error."};
  app.add_flag("--thresholds", o.thresholds, "build from YUV threshold boxes (the default when no --examples/--lut)");
  const ColourThresholds defaults;
  const std::array<const YuvRange*, 3> boxes{&defaults.ball, &defaults.line, &defaults.field};
  for (std::size_t b = 0; b < kBoxNames.size(); ++b) {
    for (std::size_t i = 0; i < kBoundNames.size(); ++i) {
      YuvRange copy = *boxes[b];
      const std::string name = std::string("--") + kBoxNames[b] + "-" + kBoundNames[i];
      app.add_option(name, o.bounds[b][i],
                     std::string("threshold box bound (default ") + std::to_string(*bound_field(copy, i)) + ")")
          ->check(CLI::Range(0, 255))
          ->group("Thresholds (full-range YUV; ball, then line, then field wins)");
    }
  }
  app.add_flag("--auto", o.auto_mode, "build from unlabelled photos (PHOTO... after the flags): the field colour is "
                                      "estimated in each, pixels classified relative to it, and the table trained on them");
  app.add_option("photos", o.photos, "photos (PNG or JPEG) for --auto, taken at the head pose given by --pitch/--yaw");
  app.add_option("--report", o.report, "--auto: write the per-photo field estimate and class fractions as JSON here");
  app.add_option("--classes-dir", o.classes_dir, "--auto: write NAME_classes.png (the classes over each photo) here");
  o.camera.add_to(app);
  app.add_option("--examples", o.examples, "build from labelled examples: a folder of *_labels.png with their pictures")
      ->check(CLI::ExistingDirectory);
  app.add_option("--stride", o.stride, "sample every N-th pixel in both directions (examples and --evaluate)")
      ->capture_default_str()->check(CLI::Range(1, 64));
  app.add_option("--fill", o.fill, "bins no example fell into: nearest labelled bin, or other")
      ->capture_default_str()->check(CLI::IsMember({"nearest", "other"}));
  app.add_option("--max-fill-distance", o.max_fill_distance, "nearest fill reaches this many bins")
      ->capture_default_str()->check(CLI::Range(0, 128));
  app.add_option("--bin-bits", o.bin_bits, "bits per channel of the table")
      ->capture_default_str()->check(CLI::Range(ColourTable::kMinBinBits, ColourTable::kMaxBinBits));
  app.add_option("--lut", o.lut, "evaluate this existing table instead of building one");
  app.add_option("-o,--out", o.out, "write the table here");
  app.add_option("--evaluate", o.evaluate, "folder of labelled images to report the table's confusion on")
      ->check(CLI::ExistingDirectory);
  app.add_option("--json", o.json, "also write the confusion as JSON here");
  app.add_flag("-q,--quiet", o.quiet, "no progress output");
  return tools::run_tool(app, argc, argv, "ringlet-vision-calibrate", [&] { return run(o); });
}
