// Whiteboard costs: post + get of a small message on the typed whiteboard against the old untyped
// style (std::mutex + unordered_map<string, string>, the message as its text), side by side; and
// the text and binary codecs. Target: typed post+get within tens of ns.
#include <benchmark/benchmark.h>

#include <array>
#include <cstddef>
#include <mutex>
#include <string>
#include <unordered_map>

#include "ringlet/whiteboard/whiteboard.hpp"

namespace {

using ringlet::wb::BallBelief;
using ringlet::wb::ExecutiveTiming;
using ringlet::wb::Whiteboard;

BallBelief ball(std::int64_t i) {
  const double x = static_cast<double>(i & 1023) * 0.001;
  return BallBelief{true, x, -x, 0.75, false};
}

void BM_TypedPostGet(benchmark::State& state) {
  Whiteboard wb(8);
  std::int64_t i = 0;
  for (auto _ : state) {
    wb.post(ball(++i));
    benchmark::DoNotOptimize(wb.get<BallBelief>());
  }
}
BENCHMARK(BM_TypedPostGet);

void BM_TypedPostGetLarge(benchmark::State& state) {  // 160-byte message
  Whiteboard wb(8);
  ExecutiveTiming t;
  for (auto _ : state) {
    ++t.frames;
    wb.post(t);
    benchmark::DoNotOptimize(wb.get<ExecutiveTiming>());
  }
}
BENCHMARK(BM_TypedPostGetLarge);

// The untyped board the class-oriented one replaces: posters format text, getters parse it.
class StringBoard {
 public:
  void post(const std::string& type, std::string value) {
    const std::lock_guard lock(mutex_);
    board_[type] = std::move(value);
  }
  std::string get(const std::string& type) const {
    const std::lock_guard lock(mutex_);
    const auto it = board_.find(type);
    return it == board_.end() ? std::string{} : it->second;
  }

 private:
  mutable std::mutex mutex_;
  std::unordered_map<std::string, std::string> board_;
};

void BM_StringBoardPostGet(benchmark::State& state) {  // raw text only, no formatting/parsing
  StringBoard wb;
  const std::string key = "BallBelief";
  const std::string text = ball(7).description();
  for (auto _ : state) {
    wb.post(key, text);
    benchmark::DoNotOptimize(wb.get(key));
  }
}
BENCHMARK(BM_StringBoardPostGet);

void BM_StringBoardPostGetWithCodec(benchmark::State& state) {  // what a typed user then pays
  StringBoard wb;
  const std::string key = "BallBelief";
  std::int64_t i = 0;
  for (auto _ : state) {
    wb.post(key, ball(++i).description());
    benchmark::DoNotOptimize(BallBelief::from_string(wb.get(key)));
  }
}
BENCHMARK(BM_StringBoardPostGetWithCodec);

void BM_Description(benchmark::State& state) {
  const BallBelief b{true, 1.2345678901234, -0.1, 0.75, false};
  for (auto _ : state) benchmark::DoNotOptimize(b.description());
}
BENCHMARK(BM_Description);

void BM_FromString(benchmark::State& state) {
  const std::string text = BallBelief{true, 1.2345678901234, -0.1, 0.75, false}.description();
  for (auto _ : state) benchmark::DoNotOptimize(BallBelief::from_string(text));
}
BENCHMARK(BM_FromString);

void BM_EncodeDecode(benchmark::State& state) {
  const BallBelief b{true, 1.2345678901234, -0.1, 0.75, false};
  std::array<std::byte, 64> buf{};
  for (auto _ : state) {
    const std::size_t n = ringlet::wb::encode(b, buf);
    benchmark::DoNotOptimize(ringlet::wb::decode<BallBelief>(std::span(buf).first(n)));
  }
}
BENCHMARK(BM_EncodeDecode);

void BM_Dispatch(benchmark::State& state) {  // one post, one cycle subscription delivered
  Whiteboard wb(8);
  double sum = 0.0;
  wb.subscribe<BallBelief>([&sum](const BallBelief& b) { sum += b.x; });
  std::int64_t i = 0;
  for (auto _ : state) {
    wb.post(ball(++i));
    wb.dispatch();
  }
  benchmark::DoNotOptimize(sum);
}
BENCHMARK(BM_Dispatch);

}  // namespace

BENCHMARK_MAIN();
