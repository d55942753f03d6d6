#include "coinspect/strategies/slei/protocol.h"

#include "coinspect/strategies/runtime/wire.h"

namespace coinspect::strategies::slei {

namespace {

using runtime::WireReader;
using runtime::WireWriter;

constexpr size_t kTaskBytes = 4 + 3 * 24 + 8;

void put(WireWriter& w, const Meeting& m) {
  w.vec3(m.place);
  w.f64(m.time);
}
bool get(WireReader& r, Meeting* m) {
  return r.vec3(&m->place) && r.f64(&m->time);
}

void put(WireWriter& w, const FeatureTask& t) {
  w.u32(t.id);
  w.vec3(t.position);
  w.vec3(t.normal);
  w.vec3(t.viewPosition);
  w.f64(t.viewYaw);
}
bool get(WireReader& r, FeatureTask* t) {
  return r.u32(&t->id) && r.vec3(&t->position) && r.vec3(&t->normal) && r.vec3(&t->viewPosition) &&
         r.f64(&t->viewYaw);
}

// A world-aligned box: centre, size, priority.
constexpr size_t kBoxBytes = 24 + 24 + 1;
void put(WireWriter& w, const agent::BoxView& b) {
  w.vec3(b.center);
  w.vec3(b.size);
  w.u8(b.highPriority ? 1 : 0);
}
bool get(WireReader& r, agent::BoxView* b) {
  uint8_t urgent = 0;
  const bool ok = r.vec3(&b->center) && r.vec3(&b->size) && r.u8(&urgent) && urgent <= 1 &&
                  (b->size.array() > 0.0).all();
  b->highPriority = urgent == 1;
  return ok;
}
// A flag byte (0 or 1), then the box when 1.
void put(WireWriter& w, const std::optional<agent::BoxView>& b) {
  w.u8(b ? 1 : 0);
  if (b) put(w, *b);
}
bool get(WireReader& r, std::optional<agent::BoxView>* b) {
  uint8_t present = 0;
  if (!r.u8(&present) || present > 1) return false;
  b->reset();
  if (present == 0) return true;
  agent::BoxView box;
  if (!get(r, &box)) return false;
  *b = box;
  return true;
}

void putIds(WireWriter& w, const std::vector<uint32_t>& ids) {
  w.u32(static_cast<uint32_t>(ids.size()));
  for (const uint32_t id : ids)
    w.u32(id);
}
bool getIds(WireReader& r, std::vector<uint32_t>* ids) {
  uint32_t n = 0;
  if (!r.count(&n, 4)) return false;
  ids->resize(n);
  for (auto& id : *ids)
    if (!r.u32(&id)) return false;
  return true;
}

template <class T>
std::optional<T> finished(WireReader& r, bool ok, T value) {
  if (!ok || !r.done()) return std::nullopt;
  return value;
}

}  // namespace

std::vector<uint8_t> encode(const FleetPlan& plan) {
  WireWriter w;
  w.u32(static_cast<uint32_t>(plan.subgroups.size()));
  for (const auto& s : plan.subgroups) {
    w.u32(s.explorer);
    putIds(w, s.inspectors);
    w.i32(s.box);
    put(w, s.firstMeeting);
    w.u32(s.station);
  }
  return w.take();
}

std::optional<FleetPlan> decodePlan(const std::vector<uint8_t>& bytes) {
  WireReader r(bytes);
  FleetPlan plan;
  uint32_t n = 0;
  bool ok = r.count(&n, 4 + 4 + 4 + 32 + 4);
  for (uint32_t i = 0; ok && i < n; ++i) {
    Subgroup s;
    ok = r.u32(&s.explorer) && getIds(r, &s.inspectors) && r.i32(&s.box) &&
         get(r, &s.firstMeeting) && r.u32(&s.station);
    plan.subgroups.push_back(std::move(s));
  }
  return finished(r, ok, std::move(plan));
}

std::vector<uint8_t> encode(const Report& report) {
  WireWriter w;
  w.i32(report.box);
  w.u8(report.boxFinished ? 1 : 0);
  w.f64(report.remaining);
  w.u32(report.meetingNumber);
  w.f64(report.energy);
  w.u32(static_cast<uint32_t>(report.remainder.size()));
  for (const auto& part : report.remainder)
    put(w, part);
  return w.take();
}

std::optional<Report> decodeReport(const std::vector<uint8_t>& bytes) {
  WireReader r(bytes);
  Report report;
  uint8_t finishedFlag = 0;
  uint32_t n = 0;
  bool ok = r.i32(&report.box) && r.u8(&finishedFlag) && finishedFlag <= 1 &&
            r.f64(&report.remaining) && r.u32(&report.meetingNumber) && r.f64(&report.energy) &&
            report.energy >= 0.0 && report.energy <= 1.0 && r.count(&n, kBoxBytes);
  report.boxFinished = finishedFlag == 1;
  report.remainder.resize(ok ? n : 0);
  for (uint32_t i = 0; ok && i < n; ++i)
    ok = get(r, &report.remainder[i]);
  return finished(r, ok, report);
}

std::vector<uint8_t> encode(const Reply& reply) {
  WireWriter w;
  w.u32(reply.meetingNumber);
  w.i32(reply.box);
  put(w, reply.next);
  w.u32(static_cast<uint32_t>(reply.stops.size()));
  for (const auto& stop : reply.stops)
    put(w, stop);
  w.u32(static_cast<uint32_t>(reply.adopt.size()));
  for (const auto& a : reply.adopt) {
    w.u32(a.inspector);
    w.vec3(a.place);
  }
  w.u8(reply.dropInspectors ? 1 : 0);
  w.f64(reply.chargeFrom);
  put(w, reply.boxShape);
  w.i32(reply.nextBox);
  put(w, reply.nextBoxShape);
  return w.take();
}

std::optional<Reply> decodeReply(const std::vector<uint8_t>& bytes) {
  WireReader r(bytes);
  Reply reply;
  uint32_t n = 0;
  bool ok =
      r.u32(&reply.meetingNumber) && r.i32(&reply.box) && get(r, &reply.next) && r.count(&n, 32);
  reply.stops.resize(ok ? n : 0);
  for (uint32_t i = 0; ok && i < n; ++i)
    ok = get(r, &reply.stops[i]);
  ok = ok && r.count(&n, 4 + 24);
  reply.adopt.resize(ok ? n : 0);
  for (uint32_t i = 0; ok && i < n; ++i)
    ok = r.u32(&reply.adopt[i].inspector) && r.vec3(&reply.adopt[i].place);
  uint8_t drop = 0;
  ok = ok && r.u8(&drop) && drop <= 1 && r.f64(&reply.chargeFrom) && get(r, &reply.boxShape);
  reply.dropInspectors = drop == 1;
  ok = ok && r.i32(&reply.nextBox) && reply.nextBox >= -1 && get(r, &reply.nextBoxShape);
  return finished(r, ok, std::move(reply));
}

std::vector<uint8_t> encode(const Orders& orders) {
  WireWriter w;
  w.u32(orders.sequence);
  w.u32(static_cast<uint32_t>(orders.tasks.size()));
  for (const auto& t : orders.tasks)
    put(w, t);
  w.u8(orders.waitAt ? 1 : 0);
  if (orders.waitAt) w.vec3(*orders.waitAt);
  return w.take();
}

std::optional<Orders> decodeOrders(const std::vector<uint8_t>& bytes) {
  WireReader r(bytes);
  Orders orders;
  uint32_t n = 0;
  bool ok = r.u32(&orders.sequence) && r.count(&n, kTaskBytes);
  for (uint32_t i = 0; ok && i < n; ++i) {
    FeatureTask t;
    ok = get(r, &t);
    orders.tasks.push_back(t);
  }
  uint8_t hasWait = 0;
  ok = ok && r.u8(&hasWait) && hasWait <= 1;
  if (ok && hasWait) {
    Vec3 p;
    ok = r.vec3(&p);
    orders.waitAt = p;
  }
  return finished(r, ok, std::move(orders));
}

std::vector<uint8_t> encode(const Status& status) {
  WireWriter w;
  w.u32(status.lastOrders);
  putIds(w, status.inspected);
  w.u32(status.listLeft);
  return w.take();
}

std::optional<Status> decodeStatus(const std::vector<uint8_t>& bytes) {
  WireReader r(bytes);
  Status status;
  const bool ok =
      r.u32(&status.lastOrders) && getIds(r, &status.inspected) && r.u32(&status.listLeft);
  return finished(r, ok, std::move(status));
}

}  // namespace coinspect::strategies::slei
