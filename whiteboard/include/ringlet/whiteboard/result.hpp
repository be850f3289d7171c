#pragma once
// Result<T>: a value or an error message (std::expected is C++23; this is the small part of it we
// need). The error path may allocate; the success path never does.
#include <optional>
#include <string>
#include <utility>

namespace ringlet::wb {

struct Error {
  std::string message;
};

template <class T>
class [[nodiscard]] Result {
 public:
  Result(T value) noexcept(std::is_nothrow_move_constructible_v<T>)  // NOLINT: like std::expected
      : value_(std::move(value)) {}
  Result(Error e) : error_(std::move(e.message)) {}  // NOLINT

  [[nodiscard]] bool has_value() const noexcept { return value_.has_value(); }
  explicit operator bool() const noexcept { return has_value(); }
  [[nodiscard]] const T& value() const& { return value_.value(); }
  [[nodiscard]] T& value() & { return value_.value(); }
  [[nodiscard]] const T& operator*() const& { return *value_; }
  [[nodiscard]] const T* operator->() const { return &*value_; }
  /// Empty when there is a value.
  [[nodiscard]] const std::string& error() const noexcept { return error_; }

 private:
  std::optional<T> value_;
  std::string error_;
};

/// Result of an operation with no value: ok, or an error message.
class [[nodiscard]] Status {
 public:
  Status() noexcept = default;
  Status(Error e) : error_(std::move(e.message)), ok_(false) {}  // NOLINT
  [[nodiscard]] bool ok() const noexcept { return ok_; }
  explicit operator bool() const noexcept { return ok_; }
  [[nodiscard]] const std::string& error() const noexcept { return error_; }

 private:
  std::string error_;
  bool ok_ = true;
};

}  // namespace ringlet::wb
