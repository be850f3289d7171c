#include "ringlet/remote/domain.hpp"

#include <map>
#include <mutex>

namespace ringlet::remote {
namespace {

// The domains this process has configured: Cyclone DDS configures a domain once per process
// (dds_create_domain), and deleting the domain deletes every participant in it, so the domain
// lives as long as its last participant here.
struct DomainEntry {
  dds_entity_t domain = 0;
  std::string config;
  int participants = 0;
};
std::mutex g_domains_mutex;
std::map<std::uint32_t, DomainEntry>& domains() {
  static std::map<std::uint32_t, DomainEntry> d;
  return d;
}

std::string where(const DomainConfig& c) {
  return "DDS domain " + std::to_string(c.id) + " (partition \"" + c.partition + "\")";
}

}  // namespace

dds_return_t check(dds_return_t rc, const std::string& what) {
  if (rc < 0) throw RemoteError(what + ": " + dds_strretcode(rc));
  return rc;
}

std::string loopback_config() {
  // Participant indices let unicast discovery find every participant on 127.0.0.1 without
  // multicast: each takes the next free index and its ports, the peers are probed up to the
  // maximum (robots, monitors and test processes on one machine).
  return "<CycloneDDS><Domain Id=\"any\">"
         "<General><Interfaces><NetworkInterface name=\"lo\"/></Interfaces>"
         "<AllowMulticast>false</AllowMulticast></General>"
         "<Discovery><ParticipantIndex>auto</ParticipantIndex>"
         "<MaxAutoParticipantIndex>40</MaxAutoParticipantIndex>"
         "<Peers><Peer Address=\"127.0.0.1\"/></Peers></Discovery>"
         "<Internal><HeartbeatInterval min=\"1ms\" minsched=\"1ms\">5ms</HeartbeatInterval></Internal>"
         "</Domain></CycloneDDS>";
}

TopicQos topic_qos(wb::TypeId type) noexcept {
  switch (wb::to_underlying(type)) {
    case wb::to_underlying(wb::FsmStatus::kId):
      // Deep enough that a monitor on the same machine gets every status of a run (the bridge
      // paces a lockstep run on the acknowledgements); a late joiner reads the newest.
      return {TopicKind::kState, 256};
    case wb::to_underlying(wb::Print::kId):
      return {TopicKind::kState, 16};
    case wb::to_underlying(wb::Plan::kId):
    case wb::to_underlying(wb::MissionGoals::kId):
    case wb::to_underlying(wb::MissionStatus::kId):
      return {TopicKind::kState, 1};
    case wb::to_underlying(wb::FsmControl::kId):
      return {TopicKind::kCommand, 0};
    default:
      return {TopicKind::kTelemetry, 1};
  }
}

const char* to_string(TopicKind kind) noexcept {
  switch (kind) {
    case TopicKind::kState: return "state";
    case TopicKind::kTelemetry: return "telemetry";
    case TopicKind::kCommand: return "command";
  }
  return "?";
}

Qos::Qos(const TopicQos& q) : qos_(dds_create_qos()) {
  switch (q.kind) {
    case TopicKind::kState:
      dds_qset_reliability(qos_, DDS_RELIABILITY_RELIABLE, DDS_SECS(1));
      dds_qset_durability(qos_, DDS_DURABILITY_TRANSIENT_LOCAL);
      dds_qset_history(qos_, DDS_HISTORY_KEEP_LAST, q.depth);
      break;
    case TopicKind::kTelemetry:
      dds_qset_reliability(qos_, DDS_RELIABILITY_BEST_EFFORT, 0);
      dds_qset_durability(qos_, DDS_DURABILITY_VOLATILE);
      dds_qset_history(qos_, DDS_HISTORY_KEEP_LAST, q.depth);
      break;
    case TopicKind::kCommand:
      dds_qset_reliability(qos_, DDS_RELIABILITY_RELIABLE, DDS_SECS(1));
      dds_qset_durability(qos_, DDS_DURABILITY_VOLATILE);
      dds_qset_history(qos_, DDS_HISTORY_KEEP_ALL, DDS_LENGTH_UNLIMITED);
      break;
  }
  if (q.keep_all) dds_qset_history(qos_, DDS_HISTORY_KEEP_ALL, DDS_LENGTH_UNLIMITED);
}

Participant::Participant(const DomainConfig& config) : config_(config) {
  const std::string xml = config.cyclone_config.empty() ? loopback_config() : config.cyclone_config;
  {
    const std::lock_guard lock(g_domains_mutex);
    DomainEntry& e = domains()[config.id];
    if (e.participants == 0) {
      e.domain = check(dds_create_domain(config.id, xml.c_str()), "configuring " + where(config));
      e.config = xml;
    } else if (e.config != xml) {
      throw RemoteError(where(config) + " is already configured differently in this process");
    }
    ++e.participants;
  }
  try {
    participant_ = check(dds_create_participant(config.id, nullptr, nullptr), "joining " + where(config));
    const char* partition = config.partition.c_str();
    dds_qos_t* qos = dds_create_qos();
    dds_qset_partition1(qos, partition);
    publisher_ = dds_create_publisher(participant_, qos, nullptr);
    subscriber_ = dds_create_subscriber(participant_, qos, nullptr);
    dds_delete_qos(qos);
    check(publisher_, "creating the publisher in " + where(config));
    check(subscriber_, "creating the subscriber in " + where(config));
  } catch (...) {
    release();
    throw;
  }
}

Participant::~Participant() { release(); }

void Participant::release() noexcept {
  if (participant_ > 0) dds_delete(participant_);
  participant_ = 0;
  const std::lock_guard lock(g_domains_mutex);
  auto it = domains().find(config_.id);
  if (it == domains().end()) return;
  if (--it->second.participants == 0) {
    dds_delete(it->second.domain);
    domains().erase(it);
  }
}

dds_entity_t Participant::create_topic(const dds_topic_descriptor_t* descriptor, const std::string& name) {
  return check(dds_create_topic(participant_, descriptor, name.c_str(), nullptr, nullptr),
               "creating topic " + name + " in " + where(config_));
}

dds_entity_t Participant::create_writer(dds_entity_t topic, wb::TypeId id) {
  const Qos qos(topic_qos(id));
  return check(dds_create_writer(publisher_, topic, qos.get(), nullptr), "creating a writer in " + where(config_));
}

dds_entity_t Participant::create_reader(dds_entity_t topic, wb::TypeId id, bool keep_all) {
  TopicQos q = topic_qos(id);
  q.keep_all = keep_all;
  const Qos qos(q);
  return check(dds_create_reader(subscriber_, topic, qos.get(), nullptr), "creating a reader in " + where(config_));
}

dds_entity_t Participant::create_request_entity(dds_entity_t topic, bool writer) {
  const Qos qos({TopicKind::kCommand, 0});
  if (writer) return check(dds_create_writer(publisher_, topic, qos.get(), nullptr), "creating a request writer in " + where(config_));
  return check(dds_create_reader(subscriber_, topic, qos.get(), nullptr), "creating a request reader in " + where(config_));
}

}  // namespace ringlet::remote
