// The pipe between tamias_bench and an engine worker (engine_worker.cpp): commands one way,
// replies the other, in native binary (both ends are built together for the same machine, so
// doubles cross bit for bit and both engines build exactly the same SceneDesc).
//
// A command is an Op and its arguments; a reply is a status byte (0: done, 1: failed, then the
// message), the worker's live heap (bytes, after the command) and the command's results.
#pragma once

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "bench_scenes.hpp"

namespace tamias_bench::wire {

enum class Op : std::uint8_t {
    build = 'B',   ///< SceneDesc -> (): replaces the worker's engine
    timed = 'T',   ///< int32 n -> StepTimes: n steps, timed in the worker
    steps = 'S',   ///< int32 n -> (): n steps, untimed
    probes = 'P',  ///< () -> int32 count, count x Probe: every body of the scene
    release = 'R', ///< () -> (): destroys the engine
    /// int32 n -> (): the substeps of the engines built from now on (0: the benchmark's 4)
    substeps = 'N',
    /// int32 rays, int32 casts, uint64 seed -> QueryTimes: the query workload
    /// (query_bench.hpp) drawn from the worker's scene, timed in the worker
    queries = 'Q',
};

/// Collects a message and sends it in one go.
class Writer {
  public:
    template <class T> void put(const T& v) {
        static_assert(std::is_trivially_copyable_v<T>);
        const auto* p = reinterpret_cast<const char*>(&v);
        buf_.append(p, sizeof(T));
    }
    void put_string(const std::string& s) {
        put(std::int32_t(s.size()));
        buf_.append(s);
    }
    /// Writes the whole message to `fd`; throws if the other end has gone.
    void send(int fd) {
        std::size_t done = 0;
        while (done < buf_.size()) {
            const ssize_t n = ::write(fd, buf_.data() + done, buf_.size() - done);
            if (n < 0 && errno == EINTR)
                continue;
            if (n <= 0)
                throw std::runtime_error(std::string("pipe write: ") + std::strerror(errno));
            done += std::size_t(n);
        }
        buf_.clear();
    }

  private:
    std::string buf_;
};

/// Reads a message field by field from `fd`; throws at the end of the stream.
class Reader {
  public:
    explicit Reader(int fd) : fd_(fd) {}
    template <class T> T get() {
        static_assert(std::is_trivially_copyable_v<T>);
        T v;
        read_exactly(reinterpret_cast<char*>(&v), sizeof(T));
        return v;
    }
    std::string get_string() {
        std::string s(std::size_t(get<std::int32_t>()), '\0');
        read_exactly(s.data(), s.size());
        return s;
    }
    /// False at a clean end of the stream (the other end closed it between messages).
    bool more() {
        fill();
        return pos_ < end_;
    }

  private:
    void fill() {
        if (pos_ < end_)
            return;
        for (;;) {
            const ssize_t n = ::read(fd_, buf_, sizeof buf_);
            if (n < 0 && errno == EINTR)
                continue;
            pos_ = 0;
            end_ = n > 0 ? std::size_t(n) : 0;
            return;
        }
    }
    void read_exactly(char* out, std::size_t size) {
        while (size > 0) {
            fill();
            if (pos_ == end_)
                throw std::runtime_error("pipe closed");
            const std::size_t k = std::min(size, end_ - pos_);
            std::memcpy(out, buf_ + pos_, k);
            pos_ += k;
            out += k;
            size -= k;
        }
    }
    int fd_;
    char buf_[65536];
    std::size_t pos_ = 0, end_ = 0;
};

inline void put_v2(Writer& w, V2 v) {
    w.put(v.x);
    w.put(v.y);
}
inline V2 get_v2(Reader& r) {
    const double x = r.get<double>();
    return {x, r.get<double>()};
}

inline void put_scene(Writer& w, const SceneDesc& s) {
    w.put_string(s.name);
    w.put(s.kind);
    put_v2(w, s.gravity);
    w.put(s.dt);
    w.put(std::int32_t(s.bodies.size()));
    for (const BodyDesc& b : s.bodies) {
        w.put(b.dynamic);
        put_v2(w, b.position);
        w.put(b.angle);
        put_v2(w, b.velocity);
        w.put(std::int32_t(b.boxes.size()));
        for (const BoxPart& p : b.boxes) {
            put_v2(w, p.center);
            w.put(p.hx);
            w.put(p.hy);
            w.put(p.angle);
        }
        w.put(b.density);
        w.put(b.friction);
        w.put(b.restitution);
        w.put(b.mass);
        w.put(b.inertia);
    }
    w.put(std::int32_t(s.dynamic_count));
    w.put(std::int32_t(s.tops.size()));
    for (const int t : s.tops)
        w.put(std::int32_t(t));
    w.put(s.inner_half_w);
    w.put(s.box);
    w.put(s.speed);
    w.put(s.sleep);
    w.put(std::int32_t(s.joints.size()));
    for (const JointDesc& j : s.joints) {
        w.put(std::int32_t(j.a));
        w.put(std::int32_t(j.b));
        put_v2(w, j.anchor);
    }
    w.put(s.apart_separation);
    w.put(s.mass_ratio);
}

inline SceneDesc get_scene(Reader& r) {
    SceneDesc s;
    s.name = r.get_string();
    s.kind = r.get<SceneKind>();
    s.gravity = get_v2(r);
    s.dt = r.get<double>();
    s.bodies.resize(std::size_t(r.get<std::int32_t>()));
    for (BodyDesc& b : s.bodies) {
        b.dynamic = r.get<bool>();
        b.position = get_v2(r);
        b.angle = r.get<double>();
        b.velocity = get_v2(r);
        b.boxes.resize(std::size_t(r.get<std::int32_t>()));
        for (BoxPart& p : b.boxes) {
            p.center = get_v2(r);
            p.hx = r.get<double>();
            p.hy = r.get<double>();
            p.angle = r.get<double>();
        }
        b.density = r.get<double>();
        b.friction = r.get<double>();
        b.restitution = r.get<double>();
        b.mass = r.get<double>();
        b.inertia = r.get<double>();
    }
    s.dynamic_count = r.get<std::int32_t>();
    s.tops.resize(std::size_t(r.get<std::int32_t>()));
    for (int& t : s.tops)
        t = r.get<std::int32_t>();
    s.inner_half_w = r.get<double>();
    s.box = r.get<double>();
    s.speed = r.get<double>();
    s.sleep = r.get<bool>();
    s.joints.resize(std::size_t(r.get<std::int32_t>()));
    for (JointDesc& j : s.joints) {
        j.a = r.get<std::int32_t>();
        j.b = r.get<std::int32_t>();
        j.anchor = get_v2(r);
    }
    s.apart_separation = r.get<double>();
    s.mass_ratio = r.get<double>();
    return s;
}

} // namespace tamias_bench::wire
