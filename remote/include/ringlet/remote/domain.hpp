#pragma once
// Joining a DDS domain: the Cyclone DDS configuration, the participant, the partition, and the
// QoS every whiteboard topic gets. The firmware's bridge and ringlet-monitor both build on this, so
// a monitor always asks for what the robot offers.
//
// Configuration. By default Cyclone DDS is told to use the loopback interface only, with no
// multicast and 127.0.0.1 as the one discovery peer (loopback_config()), so that tests and CI
// never leave the machine. A robot on a team network gets its own XML (remote/README.md).
// Partition: robots of one team share a partition (e.g. the team's name); a test run picks a
// partition of its own so that runs side by side never see each other.
//
// QoS, per type (topic_qos):
//   kState      reliable, transient-local, keep the last `depth` per instance: a monitor that
//               starts late still gets every robot's current FSM states, plan and mission
//   kTelemetry  best-effort, keep the last one: high-rate sensor and vision data, where the newest
//               sample is the one worth having
//   kCommand    reliable, volatile: remote requests (FsmControl, mission goals), never replayed to
//               a robot that starts later
#include <dds/dds.h>

#include <array>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "ringlet/remote/topics.hpp"
#include "ringlet/whiteboard/messages.hpp"

namespace ringlet::remote {

/// A DDS call failed at start-up (the message names the call, the domain and DDS's reason).
class RemoteError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct DomainConfig {
  std::uint32_t id = 0;             // DDS domain id (0-232)
  std::string partition = "ringlet";
  std::string cyclone_config;       // Cyclone DDS XML (text, or file:// URIs); empty: loopback_config()
};

/// Loopback only: interface lo, no multicast, peer 127.0.0.1.
[[nodiscard]] std::string loopback_config();

enum class TopicKind : std::uint8_t { kState, kTelemetry, kCommand };
struct TopicQos {
  TopicKind kind = TopicKind::kTelemetry;
  std::int32_t depth = 1;  // history per instance (kState, kTelemetry); kCommand keeps all
  bool keep_all = false;   // a reader that records everything it receives (ringlet-monitor echo, record)
};
[[nodiscard]] TopicQos topic_qos(wb::TypeId type) noexcept;
[[nodiscard]] const char* to_string(TopicKind kind) noexcept;

/// A dds_qos_t owned for one scope.
class Qos {
 public:
  explicit Qos(const TopicQos& q);
  ~Qos() { dds_delete_qos(qos_); }
  Qos(const Qos&) = delete;
  Qos& operator=(const Qos&) = delete;
  [[nodiscard]] const dds_qos_t* get() const noexcept { return qos_; }

 private:
  dds_qos_t* qos_;
};

/// A participant in a configured domain, with one publisher and one subscriber in the partition.
/// Several participants in one process share the domain's configuration; a second one asking for
/// another configuration of the same domain id is refused (RemoteError).
class Participant {
 public:
  explicit Participant(const DomainConfig& config);
  ~Participant();
  Participant(const Participant&) = delete;
  Participant& operator=(const Participant&) = delete;

  [[nodiscard]] dds_entity_t handle() const noexcept { return participant_; }
  [[nodiscard]] dds_entity_t publisher() const noexcept { return publisher_; }
  [[nodiscard]] dds_entity_t subscriber() const noexcept { return subscriber_; }
  [[nodiscard]] const DomainConfig& config() const noexcept { return config_; }

  /// The topic of T in this participant (created on first use).
  template <wb::Message T>
  [[nodiscard]] dds_entity_t topic() {
    dds_entity_t& t = topics_[wb::kIndexOf<T>];
    if (t == 0) t = create_topic(DdsType<T>::descriptor(), topic_name(T::kName));
    return t;
  }
  /// The request topic of T (remote writes to a robot: request_topic_name), and its writer (a
  /// monitor) and reader (the robot's bridge): reliable, volatile, every request kept.
  template <wb::Message T>
  [[nodiscard]] dds_entity_t request_topic() {
    dds_entity_t& t = request_topics_[wb::kIndexOf<T>];
    if (t == 0) t = create_topic(DdsType<T>::descriptor(), request_topic_name(T::kName));
    return t;
  }
  template <wb::Message T>
  [[nodiscard]] dds_entity_t request_writer() {
    return create_request_entity(request_topic<T>(), true);
  }
  template <wb::Message T>
  [[nodiscard]] dds_entity_t request_reader() {
    return create_request_entity(request_topic<T>(), false);
  }

  /// A writer / reader of T with T's QoS.
  template <wb::Message T>
  [[nodiscard]] dds_entity_t writer() {
    return create_writer(topic<T>(), T::kId);
  }
  /// `keep_all`: the reader keeps every sample until taken (a recorder), instead of the topic's
  /// last `depth` per instance.
  template <wb::Message T>
  [[nodiscard]] dds_entity_t reader(bool keep_all = false) {
    return create_reader(topic<T>(), T::kId, keep_all);
  }

 private:
  void release() noexcept;  // the participant, and the domain with its last participant
  dds_entity_t create_topic(const dds_topic_descriptor_t* descriptor, const std::string& name);
  dds_entity_t create_writer(dds_entity_t topic, wb::TypeId id);
  dds_entity_t create_reader(dds_entity_t topic, wb::TypeId id, bool keep_all);
  dds_entity_t create_request_entity(dds_entity_t topic, bool writer);

  DomainConfig config_;
  dds_entity_t participant_ = 0;
  dds_entity_t publisher_ = 0;
  dds_entity_t subscriber_ = 0;
  std::array<dds_entity_t, wb::kTypeCount> topics_{};
  std::array<dds_entity_t, wb::kTypeCount> request_topics_{};
};

/// Throws RemoteError("what: reason") when rc is negative; returns rc otherwise.
dds_return_t check(dds_return_t rc, const std::string& what);

}  // namespace ringlet::remote
