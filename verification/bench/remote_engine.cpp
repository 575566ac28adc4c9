#include "remote_engine.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <cstdint>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "worker_wire.hpp"

extern char** environ;

namespace tamias_bench {

namespace {

/// The worker executable of a remote engine; empty when it was not built (CMake passes the
/// paths when TAMIAS_BOX2D_V3_DIR is set).
std::string worker_path(EngineId id) {
    switch (id) {
#ifdef TAMIAS_BENCH_V3_SSE2_WORKER
    case EngineId::box2d_v3_sse2:
        return TAMIAS_BENCH_V3_SSE2_WORKER;
#endif
#ifdef TAMIAS_BENCH_V3_AVX2_WORKER
    case EngineId::box2d_v3_avx2:
        return TAMIAS_BENCH_V3_AVX2_WORKER;
#endif
    default:
        return {};
    }
}

/// One worker process and the two pipes to it.
class Worker {
  public:
    Worker(const std::string& path, int threads, const std::vector<std::string>& extra) : in_(-1) {
        int to_child[2], from_child[2];
        if (::pipe2(to_child, O_CLOEXEC) != 0)
            throw std::runtime_error("pipe failed");
        if (::pipe2(from_child, O_CLOEXEC) != 0) {
            ::close(to_child[0]);
            ::close(to_child[1]);
            throw std::runtime_error("pipe failed");
        }
        posix_spawn_file_actions_t actions;
        posix_spawn_file_actions_init(&actions);
        posix_spawn_file_actions_adddup2(&actions, to_child[0], STDIN_FILENO);
        posix_spawn_file_actions_adddup2(&actions, from_child[1], STDOUT_FILENO);
        std::vector<std::string> args = {path, "--workers", std::to_string(threads)};
        args.insert(args.end(), extra.begin(), extra.end());
        std::vector<char*> argv;
        for (std::string& a : args)
            argv.push_back(a.data());
        argv.push_back(nullptr);
        const int rc = ::posix_spawn(&pid_, path.c_str(), &actions, nullptr, argv.data(), environ);
        posix_spawn_file_actions_destroy(&actions);
        ::close(to_child[0]);
        ::close(from_child[1]);
        to_ = to_child[1];
        in_ = wire::Reader(from_child[0]);
        from_ = from_child[0];
        if (rc != 0) {
            pid_ = -1;
            throw std::runtime_error("cannot start " + path);
        }
    }
    ~Worker() {
        ::close(to_); // the worker ends at the end of its input
        ::close(from_);
        if (pid_ > 0) {
            int status = 0;
            ::waitpid(pid_, &status, 0);
        }
    }
    Worker(const Worker&) = delete;
    Worker& operator=(const Worker&) = delete;

    /// Sends a command and reads the reply's status and heap; returns the reader positioned at
    /// the command's results. Throws the worker's error, or when the worker has gone.
    wire::Reader& call(wire::Writer& command) {
        if (!gone_.empty())
            throw std::runtime_error(gone_);
        std::uint8_t status = 0;
        std::string error;
        try {
            command.send(to_);
            status = in_.get<std::uint8_t>();
            if (status != 0)
                error = in_.get_string();
            heap_ = in_.get<double>();
        } catch (const std::exception& ex) {
            gone_ = std::string("the worker process ended (") + ex.what() + ")";
            throw std::runtime_error(gone_);
        }
        if (status != 0)
            throw std::runtime_error(error);
        return in_;
    }
    double heap() const { return heap_; }
    bool busy = false; ///< holds an engine (one at a time)

  private:
    pid_t pid_ = -1;
    int to_ = -1, from_ = -1;
    wire::Reader in_;
    double heap_ = 0.0;
    std::string gone_;
};

std::vector<std::string> worker_arguments; ///< set_remote_engine_arguments

/// The running workers by engine and v3 worker count (tamias_bench: 1 each).
std::map<std::pair<EngineId, int>, std::unique_ptr<Worker>> workers;

wire::Writer command(wire::Op op) {
    wire::Writer w;
    w.put(op);
    return w;
}

class RemoteEngine final : public Engine {
  public:
    RemoteEngine(Worker& worker, const SceneDesc& s, int substeps)
        : worker_(worker), bodies_(s.bodies.size()) {
        if (worker_.busy)
            throw std::logic_error("the engine's worker already holds a scene");
        wire::Writer n = command(wire::Op::substeps); // every build: no setting outlives its run
        n.put(std::int32_t(substeps));
        worker_.call(n);
        wire::Writer c = command(wire::Op::build);
        wire::put_scene(c, s);
        worker_.call(c);
        worker_.busy = true;
    }
    ~RemoteEngine() override {
        try {
            wire::Writer c = command(wire::Op::release);
            worker_.call(c);
        } catch (const std::exception&) {
            // A worker that has gone holds no engine either.
        }
        worker_.busy = false;
    }
    RemoteEngine(const RemoteEngine&) = delete;
    RemoteEngine& operator=(const RemoteEngine&) = delete;

    void step() override {
        wire::Writer c = command(wire::Op::steps);
        c.put(std::int32_t(1));
        worker_.call(c);
        probes_.clear();
    }
    StepTimes timed_steps(int n) override {
        wire::Writer c = command(wire::Op::timed);
        c.put(std::int32_t(n));
        const StepTimes t = worker_.call(c).get<StepTimes>();
        probes_.clear();
        return t;
    }
    /// The worker draws the same workload from its copy of the scene and the seed.
    QueryTimes timed_queries(const QueryLoad& load) override {
        wire::Writer c = command(wire::Op::queries);
        c.put(std::int32_t(load.ray_count));
        c.put(std::int32_t(load.cast_count));
        c.put(load.seed);
        return worker_.call(c).get<QueryTimes>();
    }
    /// Every body's state comes over in one reply, fetched at the first probe after a step.
    Probe probe(int index) const override {
        if (probes_.empty()) {
            wire::Writer c = command(wire::Op::probes);
            wire::Reader& r = worker_.call(c);
            probes_.resize(std::size_t(r.get<std::int32_t>()));
            for (Probe& p : probes_)
                p = r.get<Probe>();
            if (probes_.size() != bodies_)
                throw std::runtime_error("the worker reported another number of bodies");
        }
        return probes_[std::size_t(index)];
    }

  private:
    Worker& worker_;
    std::size_t bodies_;
    mutable std::vector<Probe> probes_;
};

} // namespace

bool is_remote(EngineId id) {
    return id == EngineId::box2d_v3_sse2 || id == EngineId::box2d_v3_avx2;
}

std::string start_remote_engine(EngineId id, int threads) {
    const auto k = std::make_pair(id, threads);
    if (workers.count(k) != 0)
        return {};
    const std::string path = worker_path(id);
    if (path.empty())
        return "not measured: tamias_bench was built without TAMIAS_BOX2D_V3_DIR";
    if (id == EngineId::box2d_v3_avx2 && !__builtin_cpu_supports("avx2"))
        return "not measured: this machine has no AVX2";
    // A worker that has gone must not take tamias_bench with it when a command is written.
    std::signal(SIGPIPE, SIG_IGN);
    try {
        auto w = std::make_unique<Worker>(path, threads, worker_arguments);
        wire::Writer c = command(wire::Op::release); // answers once the worker runs
        w->call(c);
        workers[k] = std::move(w);
    } catch (const std::exception& ex) {
        return std::string("not measured: ") + ex.what();
    }
    return {};
}

void set_remote_engine_arguments(std::vector<std::string> arguments) {
    worker_arguments = std::move(arguments);
}

double remote_heap_bytes(EngineId id) {
    const auto w = workers.find({id, 1});
    return w == workers.end() ? 0.0 : w->second->heap();
}

std::unique_ptr<Engine> make_remote_engine(EngineId id, const SceneDesc& scene, int threads,
                                           int substeps) {
    const auto w = workers.find({id, threads});
    if (w == workers.end())
        throw std::runtime_error("its worker is not running");
    return std::make_unique<RemoteEngine>(*w->second, scene, substeps);
}

std::string remote_engines_description() {
#ifdef TAMIAS_BENCH_V3_VERSION
    return std::string("Box2D v3 ") + TAMIAS_BENCH_V3_VERSION +
           " from " TAMIAS_BENCH_V3_SOURCE ", " TAMIAS_BENCH_V3_C_FLAGS
           ", float; the SSE2 build (v3's default) and the AVX2 "
           "build (-mavx2, BOX2D_AVX2, where the machine has AVX2), each in a worker process of "
           "its own; b2DefaultWorldDef (contact 30 Hz, damping ratio 10, continuous collision "
           "on), 4 substeps, 1 worker thread, sleeping off (pyramid40_sleep: on, b2_timeToSleep "
           "0.5 s); joints: b2RevoluteJoint with its defaults (60 Hz, damping ratio 2)";
#else
    return "not measured: tamias_bench was built without TAMIAS_BOX2D_V3_DIR";
#endif
}

void stop_remote_engines() {
    workers.clear();
}

} // namespace tamias_bench
