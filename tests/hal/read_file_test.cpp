// The bounded file reader: regular files only, a size limit, messages that name the file.
#include "ringlet/hal/read_file.hpp"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "temp_dir.hpp"

namespace {

namespace fs = std::filesystem;
using ringlet::hal::read_file;

// One folder per test process, removed when it exits.
fs::path temp_dir() {
  static const ringlet::test::TempDir dir("ringlet_read_file");
  return dir.path();
}

TEST(ReadFile, ReadsARegularFileWhole) {
  const auto p = temp_dir() / "a.txt";
  std::ofstream(p) << "hello\nworld";
  const auto r = read_file(p, "test file");
  ASSERT_TRUE(r.ok()) << r.error;
  EXPECT_EQ(r.bytes, "hello\nworld");
}

TEST(ReadFile, RefusesAMissingFileNamingIt) {
  const auto r = read_file("/nonexistent/ringlet.toml", "configuration file");
  EXPECT_FALSE(r.ok());
  EXPECT_NE(r.error.find("/nonexistent/ringlet.toml: cannot read configuration file: "), std::string::npos) << r.error;
}

TEST(ReadFile, RefusesADirectory) {
  const auto r = read_file(temp_dir(), "world file");
  EXPECT_NE(r.error.find("not a regular file (a directory)"), std::string::npos) << r.error;
  EXPECT_TRUE(r.bytes.empty());
}

TEST(ReadFile, RefusesADeviceWithoutReadingIt) {
  const auto r = read_file("/dev/zero", "world file");
  EXPECT_NE(r.error.find("not a regular file (a character device)"), std::string::npos) << r.error;
}

TEST(ReadFile, RefusesAFifoWithoutBlocking) {
  const auto p = temp_dir() / "fifo";
  fs::remove(p);
  ASSERT_EQ(::mkfifo(p.c_str(), 0600), 0);
  const auto r = read_file(p, "configuration file");  // would block forever if opened blocking
  EXPECT_NE(r.error.find("not a regular file (a FIFO)"), std::string::npos) << r.error;
  fs::remove(p);
}

TEST(ReadFile, RefusesAFileOverTheLimit) {
  const auto p = temp_dir() / "big.txt";
  std::ofstream(p) << std::string(101, 'x');
  const auto r = read_file(p, "model", 100);
  EXPECT_NE(r.error.find("too large (101 bytes; the limit is 100)"), std::string::npos) << r.error;
  EXPECT_TRUE(read_file(p, "model", 101).ok());
}

}  // namespace
