#pragma once
// Shared by the remote tests: a DDS partition of the running test's own (tests side by side in one
// domain never see each other's samples), waiting for a condition with a generous timeout, and
// waiting for a writer's readers to match.
#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <string>
#include <thread>

#include "ringlet/remote/domain.hpp"

namespace ringlet::remote::test {

inline DomainConfig test_domain() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  return {0, std::string("ringlet-test-") + std::to_string(::getpid()) + "-" + info->name(), ""};
}

template <class Pred>
bool eventually(Pred pred, std::chrono::milliseconds timeout = std::chrono::seconds{10}) {
  const auto end = std::chrono::steady_clock::now() + timeout;
  while (std::chrono::steady_clock::now() < end) {
    if (pred()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds{2});
  }
  return pred();
}

/// True once `writer` has at least one matched reader (within the timeout).
inline bool reader_matched(dds_entity_t writer) {
  return eventually([&] {
    dds_publication_matched_status_t st{};
    return dds_get_publication_matched_status(writer, &st) == 0 && st.current_count >= 1;
  });
}

}  // namespace ringlet::remote::test
