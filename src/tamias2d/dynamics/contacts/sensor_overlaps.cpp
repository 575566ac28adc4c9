#include "tamias2d/dynamics/contacts/sensor_overlaps.hpp"

#include <algorithm>
#include <string>

#include "tamias2d/collision/narrow_phase.hpp"
#include "tamias2d/dynamics/body_store.hpp"
#include "tamias2d/dynamics/contacts/contact_manager.hpp"
#include "tamias2d/dynamics/shape_store.hpp"
#include "tamias2d/dynamics/snapshot_io.hpp"
#include "tamias2d/memory/allocator.hpp"
#include "tamias2d/model/dd28_sensor_overlap.hpp"

namespace tamias2d {
namespace {

SensorEvent event(std::uint32_t sensor, std::uint32_t visitor, const BodyStore& bodies,
                  const ShapeStore& shapes) {
    return {shapes.id(sensor), shapes.id(visitor), bodies.id(shapes.shapes[sensor].body),
            bodies.id(shapes.shapes[visitor].body)};
}

/// DD28's overlap of two shapes in their current poses, from R7's manifold.
bool overlap(const Shape& a, const Shape& b) {
    const CollideInput in{a.body_xf, a.body_center, b.body_xf, b.body_center, 0.0};
    Manifold m{};
    collide(a.collider, b.collider, in, m);
    double least = 0.0;
    for (int k = 0; k < m.count; ++k)
        least = k == 0 ? m.points[k].separation : std::min(least, m.points[k].separation);
    return model::dd28::overlapping(m.count, units::Length::from_value(least));
}

} // namespace

void SensorOverlaps::add(std::uint32_t sensor_shape) {
    sensors_.push_back({sensor_shape, {}});
}

void SensorOverlaps::remove_shape(std::uint32_t s, const BodyStore& bodies,
                                  const ShapeStore& shapes) {
    for (std::size_t i = 0; i < sensors_.size();) {
        Sensor& sensor = sensors_[i];
        if (sensor.shape == s) {
            for (const std::uint32_t v : sensor.visitors)
                end_events.push_back(event(s, v, bodies, shapes));
            sensors_.erase(sensors_.begin() + std::ptrdiff_t(i));
            continue;
        }
        const auto it = std::lower_bound(sensor.visitors.begin(), sensor.visitors.end(), s);
        if (it != sensor.visitors.end() && *it == s) {
            end_events.push_back(event(sensor.shape, s, bodies, shapes));
            sensor.visitors.erase(it);
        }
        ++i;
    }
}

void SensorOverlaps::update(const BodyStore& bodies, const ShapeStore& shapes,
                            const ContactManager& rules) {
    for (Sensor& sensor : sensors_) {
        const Shape& ss = shapes.shapes[sensor.shape];
        const Body& sb = bodies.bodies[ss.body];
        now_.clear();
        // A sensor whose events are off, or a disabled body's (World::set_enabled), detects
        // nothing: its overlaps end, with end events.
        const bool detects = shapes.defs[sensor.shape].enable_sensor_events;
        const auto visit = [&](int proxy) {
            const std::uint32_t v = shapes.broad_phase.user_data(proxy);
            const Shape& vs = shapes.shapes[v];
            const ShapeDef& vd = shapes.defs[v];
            // Not itself or its own body, not another sensor, not a shape whose sensor events
            // are off, not a disabled body's, not two static bodies; the filters (DD27) and the
            // game's filter decide the rest, as for contacts.
            if (vs.body == ss.body || vd.is_sensor || !vd.enable_sensor_events ||
                bodies.disabled(vs.body) ||
                (sb.type == BodyType::static_body &&
                 bodies.bodies[vs.body].type == BodyType::static_body) ||
                !admits(shapes.defs[sensor.shape].filter, vd.filter) ||
                !rules.custom_admits(shapes.id(sensor.shape), shapes.id(v)))
                return true;
            if (overlap(ss, vs))
                now_.push_back(v);
            return true;
        };
        if (detects && !bodies.disabled(ss.body))
            shapes.broad_phase.query(compute_aabb(ss.collider, ss.body_xf), visit);
        std::sort(now_.begin(), now_.end());
        // Both lists ascending: one merge finds who came and who went.
        auto before = sensor.visitors.begin();
        auto now = now_.begin();
        while (before != sensor.visitors.end() || now != now_.end()) {
            if (now == now_.end() || (before != sensor.visitors.end() && *before < *now)) {
                end_events.push_back(event(sensor.shape, *before++, bodies, shapes));
            } else if (before == sensor.visitors.end() || *now < *before) {
                begin_events.push_back(event(sensor.shape, *now++, bodies, shapes));
            } else {
                ++before;
                ++now;
            }
        }
        sensor.visitors.swap(now_);
    }
}

// --- snapshot ---

namespace {

template <class IO, class E> void sensor_event_fields(IO& io, E& e) {
    io.handle("sensor", e.sensor);
    io.handle("visitor", e.visitor);
    io.handle("sensor_body", e.sensor_body);
    io.handle("visitor_body", e.visitor_body);
}

} // namespace

void SensorOverlaps::write(SnapshotWriter& out) const {
    out.section("SENS");
    out.count("sensors", sensors_.size());
    for (const Sensor& s : sensors_) {
        out("shape", s.shape);
        out.count("visitors", s.visitors.size());
        for (const std::uint32_t v : s.visitors)
            out("visitor", v);
    }
    for (const auto* events : {&begin_events, &end_events}) {
        out.count("events", events->size());
        for (const SensorEvent& e : *events)
            sensor_event_fields(out, e);
    }
}

void SensorOverlaps::read(SnapshotReader& in, const ShapeStore& shapes) {
    in.section("SENS");
    const std::uint32_t ns = std::uint32_t(shapes.shapes.size());
    const std::size_t n = in.count("sensors", 12, ns);
    sensors_.resize(n);
    for (std::size_t k = 0; k < n; ++k) {
        in.in("sensors", k);
        Sensor& s = sensors_[k];
        const std::size_t at = in.offset();
        in.index("shape", s.shape, ns);
        in.require(shapes.slots.live(s.shape) && shapes.defs[s.shape].is_sensor, "shape",
                   "must be a live sensor shape", at);
        s.visitors.resize(in.count("visitors", 4, ns));
        for (std::size_t v = 0; v < s.visitors.size(); ++v) {
            const std::size_t here = in.offset();
            in.index("visitor", s.visitors[v], ns);
            in.require(v == 0 || s.visitors[v - 1] < s.visitors[v], "visitor",
                       "must be ascending shape indices", here);
        }
    }
    for (auto* events : {&begin_events, &end_events}) {
        in.in(nullptr);
        const std::size_t m = in.count("sensor_events", 32);
        events->resize(m);
        for (std::size_t k = 0; k < m; ++k) {
            in.in("sensor_events", k);
            sensor_event_fields(in, (*events)[k]);
        }
    }
    in.in(nullptr);
}

const memory::vector<std::uint32_t>& SensorOverlaps::visitors(std::uint32_t sensor_shape) const {
    static const memory::vector<std::uint32_t> none;
    for (const Sensor& sensor : sensors_) {
        if (sensor.shape == sensor_shape)
            return sensor.visitors;
    }
    return none;
}

} // namespace tamias2d
