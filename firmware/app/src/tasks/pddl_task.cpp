#include "ringlet/firmware/tasks/pddl_task.hpp"

#include <algorithm>
#include <cctype>
#include <cstdarg>
#include <cstdio>
#include <filesystem>

#include "ringlet/pddl/source_atom.hpp"

namespace ringlet::firmware {
namespace {

pddl::ServiceSettings service_settings(const PddlSettings& s) {
  pddl::ServiceSettings out;
  out.domain = s.domain;
  out.problems = s.problems.empty() ? s.domain.parent_path() : s.problems;
  out.places = s.places;
  out.obstacle_radius = s.obstacle_radius;
  out.arena_bytes = static_cast<std::size_t>(s.arena_kib) * 1024U;
  out.max_facts = s.max_facts;
  return out;
}

pddl::PlannerLimits limits(const PddlSettings& s) {
  pddl::PlannerLimits l;
  l.max_nodes = static_cast<std::size_t>(s.max_nodes);
  l.max_facts = s.max_facts;
  l.max_operators = s.max_operators;
  l.max_relaxed = s.max_operators;
  return l;
}

pddl::LamaOptions lama_options(const PddlSettings& s) {
  pddl::LamaOptions o;
  o.restarts = s.lama_restarts;
  return o;
}

bool same_name(std::string_view a, std::string_view b) noexcept {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
           return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y));
         });
}

std::size_t words_for(int facts) { return static_cast<std::size_t>(std::max(facts, 1) + 63) / 64; }

}  // namespace

std::unique_ptr<executive::Task> PddlTask::make(TaskServices& services) {
  const PddlSettings& p = services.config.pddl;
  if (p.domain.empty()) {
    throw ConfigError(services.config.positions.at("pddl") +
                      ": pddl.domain: the table runs the pddl task, which needs a domain file");
  }
  // LOAD_PDDL reads the files later, on the service thread; a missing domain is a start-up error.
  std::error_code ec;
  if (!std::filesystem::is_regular_file(p.domain, ec)) {
    throw ConfigError(services.config.positions.at("pddl.domain") + ": pddl.domain: " + p.domain.string() +
                      " is not a readable file");
  }
  return std::make_unique<PddlTask>(p, services.board, services.config.clock == ClockMode::kRealtime);
}

PddlTask::PddlTask(const PddlSettings& settings, wb::Whiteboard& board, bool realtime)
    : settings_(settings),
      board_(board),
      realtime_(realtime),
      worker_(service_settings(settings)),
      regression_(limits(settings)),
      lama_(limits(settings), lama_options(settings)),
      start_(words_for(settings.max_facts), 0),
      belief_(words_for(settings.max_facts), 0),
      scratch_(words_for(settings.max_facts), 0),
      in_(settings.link),
      out_(LossyLinkSettings{settings.link.drop, settings.link.duplicate, settings.link.max_delay,
                             settings.link.seed + 1}) {}

void PddlTask::run(const executive::TaskContext& /*ctx*/) noexcept {
  ++activation_;
  requests_now_ = applied_now_ = units_now_ = 0;
  // The newest request, once per generation: the requester posts it every ringlet until answered.
  const std::uint64_t generation = board_.generation<wb::PddlRequest>();
  if (generation != seen_generation_) {
    seen_generation_ = generation;
    in_.push(board_.get<wb::PddlRequest>(), activation_);
  }
  wb::PddlRequest r;
  while (in_.pop(activation_, r)) handle(r);  // at most the link's capacity
  if (busy_ == Busy::kWorker) take_worker_result();
  if (busy_ == Busy::kSearch) step_search();
  wb::PddlReply reply;
  while (out_.pop(activation_, reply)) board_.post(reply);
  cost_ = kBaseCost + kCostPerRequest * static_cast<std::int64_t>(requests_now_) +
          kCostPerUnit * static_cast<std::int64_t>(units_now_) + kCostPerApplied * static_cast<std::int64_t>(applied_now_);
}

void PddlTask::handle(const wb::PddlRequest& r) noexcept {
  if (r.id == 0 || r.op == wb::PddlOp::kNone) return;
  ++counts_.requests;
  ++requests_now_;
  if (r.id < last_id_) {
    ++counts_.stale;
  } else if (r.id == last_id_) {
    if (replied_) {
      ++counts_.repeated;
      send(last_reply_);
    }
  } else if (busy_ != Busy::kNone) {
    ++counts_.busy;
  } else {
    ++counts_.carried_out;
    last_id_ = r.id;
    replied_ = false;
    current_ = r;
    begin(r);
  }
}

void PddlTask::begin(const wb::PddlRequest& r) noexcept {
  switch (r.op) {
    case wb::PddlOp::kLoadPlanner:
      if (same_name(r.text.view(), "regression")) {
        planner_ = &regression_;
      } else if (same_name(r.text.view(), "lama")) {
        planner_ = &lama_;
      } else {
        fail(r, "unknown planner \"%.*s\": regression or lama", static_cast<int>(r.text.size()), r.text.data());
        return;
      }
      {
        wb::PddlReply ok = reply_to(r, true);
        ok.reason = planner_->name();
        send(ok);
      }
      return;
    case wb::PddlOp::kLoadPddl:
      worker_.load(r.text.view());
      busy_ = Busy::kWorker;
      submitted_at_ = activation_;
      return;
    case wb::PddlOp::kStartPlanner:
    case wb::PddlOp::kReplan:
      if (task_ == nullptr) return fail(r, "no problem loaded (LOAD_PDDL first)");
      if (planner_ == nullptr) return fail(r, "no planner chosen (LOAD_PLANNER first)");
      if (r.op == wb::PddlOp::kStartPlanner) {
        std::copy(task_->initial.begin(), task_->initial.end(), start_.begin());
        std::copy(task_->initial.begin(), task_->initial.end(), belief_.begin());
      } else {
        replan(r);
        if (replied_) return;  // the source was refused
      }
      return start_search(r.depth);
    case wb::PddlOp::kNextAction:
      return next_action(r);
    case wb::PddlOp::kIsObstacleKnown:
      if (task_ == nullptr) return fail(r, "no problem loaded (LOAD_PDDL first)");
      worker_.obstacle(r.x, r.y, *task_, pddl::ConstState(belief_.data(), static_cast<std::size_t>(task_->words)));
      busy_ = Busy::kWorker;
      submitted_at_ = activation_;
      return;
    case wb::PddlOp::kNone:
      return;
  }
}

void PddlTask::replan(const wb::PddlRequest& r) noexcept {
  // From the believed state (the actions before the last one asked for are done), the source put in.
  std::copy(belief_.begin(), belief_.end(), start_.begin());
  if (r.text.empty()) return;
  const std::int32_t fact = pddl::find_fact(*task_, r.text.view());
  if (fact < 0) {
    fail(r, "source (%.*s) is not a fact of the task: an unknown predicate or object, or never reachable",
         static_cast<int>(r.text.size()), r.text.data());
    return;
  }
  pddl::put_source(*task_, pddl::State(start_.data(), static_cast<std::size_t>(task_->words)), fact);
  std::copy(start_.begin(), start_.end(), belief_.begin());
}

void PddlTask::start_search(std::int32_t depth) noexcept {
  has_plan_ = false;
  depth_ = depth > 0 ? depth : pddl::kNoHorizon;
  const pddl::PlannerStatus s =
      planner_->start(*task_, depth_, pddl::ConstState(start_.data(), static_cast<std::size_t>(task_->words)));
  busy_ = Busy::kSearch;
  if (s != pddl::PlannerStatus::kRunning) step_search();  // refused at once: reply now
}

void PddlTask::step_search() noexcept {
  pddl::PlannerStatus s = planner_->status();
  if (s == pddl::PlannerStatus::kRunning) {
    const std::uint64_t before = planner_->stats().expansions;
    s = planner_->step(static_cast<std::uint32_t>(settings_.units_per_slice));
    units_now_ += planner_->stats().expansions - before;
    counts_.max_units = std::max(counts_.max_units, static_cast<std::uint32_t>(units_now_));
  }
  if (s == pddl::PlannerStatus::kRunning) return;
  busy_ = Busy::kNone;
  switch (s) {
    case pddl::PlannerStatus::kFound: {
      has_plan_ = true;
      ++plan_number_;
      ++counts_.plans;
      wb::PddlReply ok = reply_to(current_, true);
      char text[120];
      std::snprintf(text, sizeof text, "plan %u: %zu actions (%s, %llu expansions)", plan_number_,
                    planner_->plan().size(), planner_->name(),
                    static_cast<unsigned long long>(planner_->stats().expansions));
      ok.reason = text;
      send(ok);
      return;
    }
    case pddl::PlannerStatus::kExhausted:
      if (depth_ > 0) return fail(current_, "no plan of at most %d actions from the source", depth_);
      return fail(current_, "no plan exists from the source");
    default:
      return fail(current_, "%s: %s", planner_->name(), planner_->reason());
  }
}

void PddlTask::take_worker_result() noexcept {
  // Lockstep: the activation after the request, whatever the host's speed; the real clock: the
  // first activation that finds the worker done.
  if (activation_ == submitted_at_) return;
  if (realtime_) {
    if (!worker_.idle()) return;
  } else {
    worker_.wait_idle();
  }
  busy_ = Busy::kNone;
  const pddl::ServiceResult& result = worker_.result();
  if (result.ok && result.has_task) {
    worker_.accept();
    task_storage_ = result.task;
    task_ = &task_storage_;
    has_plan_ = false;  // a plan of the old task names its operators
    std::fill(belief_.begin(), belief_.end(), 0);
    std::copy(task_->initial.begin(), task_->initial.end(), belief_.begin());
    std::copy(belief_.begin(), belief_.end(), start_.begin());
    if (current_.op == wb::PddlOp::kIsObstacleKnown) ++counts_.obstacles_added;
  }
  wb::PddlReply reply = reply_to(current_, result.ok);
  reply.reason = result.message.data();
  reply.known = result.known;
  send(reply);
}

void PddlTask::advance_belief(std::int32_t done) noexcept {
  const auto words = static_cast<std::size_t>(task_->words);
  std::copy_n(start_.begin(), words, belief_.begin());
  const auto plan = planner_->plan();
  for (std::int32_t i = 0; i < done; ++i) {
    pddl::apply(*task_, plan[static_cast<std::size_t>(i)], pddl::ConstState(belief_.data(), words),
                pddl::State(scratch_.data(), words));
    std::copy_n(scratch_.begin(), words, belief_.begin());
    ++applied_now_;
  }
}

void PddlTask::next_action(const wb::PddlRequest& r) noexcept {
  if (!has_plan_) return fail(r, "no plan (START_PLANNER or RE-PLAN first)");
  const auto plan = planner_->plan();
  const auto length = static_cast<std::int32_t>(plan.size());
  if (r.rank < 0 || r.rank >= length) {
    return fail(r, "rank %d is past the end of plan %u (%d actions)", r.rank, plan_number_, length);
  }
  advance_belief(r.rank);
  const pddl::GroundOperator& op = task_->operators[static_cast<std::size_t>(plan[static_cast<std::size_t>(r.rank)])];
  wb::PddlReply reply = reply_to(r, true);
  reply.action = task_->action_names[static_cast<std::size_t>(op.action)];
  char args[96];
  std::size_t used = 0;
  args[0] = '\0';
  const auto list = task_->list(op.args);
  reply.arg_count = static_cast<std::uint8_t>(std::min(list.size(), reply.arg_x.size()));
  for (std::size_t i = 0; i < list.size(); ++i) {
    const std::string_view name = task_->object_names[static_cast<std::size_t>(list[i])];
    const int n = std::snprintf(args + used, sizeof args - used, "%s%.*s", i == 0 ? "" : " ",
                                static_cast<int>(name.size()), name.data());
    used = std::min(sizeof args - 1, used + static_cast<std::size_t>(std::max(n, 0)));
    if (i >= reply.arg_x.size()) continue;
    for (const pddl::Place& p : settings_.places) {
      if (!same_name(p.name, name)) continue;
      reply.arg_place[i] = 1;
      reply.arg_x[i] = p.x;
      reply.arg_y[i] = p.y;
      break;
    }
  }
  reply.args = args;
  char text[120];
  // The action's text may be cut to the reply's reason; args and action carry it whole.
  const int n = std::snprintf(text, sizeof text, "action %d of %d: (%.*s %.*s)", r.rank, length,
                              static_cast<int>(reply.action.size()), reply.action.data(), static_cast<int>(used), args);
  (void)n;
  reply.reason = text;
  send(reply);
}

wb::PddlReply PddlTask::reply_to(const wb::PddlRequest& r, bool ok) const noexcept {
  wb::PddlReply reply{};
  reply.id = r.id;
  reply.op = r.op;
  reply.ok = ok;
  reply.plan = plan_number_;
  reply.plan_length = has_plan_ ? static_cast<std::int32_t>(planner_->plan().size()) : 0;
  reply.rank = r.rank;
  return reply;
}

void PddlTask::send(const wb::PddlReply& reply) noexcept {
  last_reply_ = reply;
  replied_ = true;
  out_.push(reply, activation_);
}

void PddlTask::fail(const wb::PddlRequest& r, const char* format, ...) noexcept {
  char text[120];
  va_list args;
  va_start(args, format);
  std::vsnprintf(text, sizeof text, format, args);
  va_end(args);
  busy_ = Busy::kNone;
  wb::PddlReply reply = reply_to(r, false);
  reply.reason = text;
  send(reply);
}

}  // namespace ringlet::firmware
