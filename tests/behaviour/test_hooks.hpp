#pragma once
// A hook the Echo test model calls in the middle of its Internal action, so that a test can post
// to the whiteboard "while" the machine runs (as another writer would) and check the snapshot.
#include <functional>

namespace ringlet::behaviour::llfsm::test {

inline std::function<void()>& probe_hook() {
  static std::function<void()> hook;
  return hook;
}

inline void probe() {
  if (probe_hook()) probe_hook()();
}

}  // namespace ringlet::behaviour::llfsm::test
