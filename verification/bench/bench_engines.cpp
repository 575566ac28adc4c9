#include "bench_engines.hpp"

#include <cmath>
#include <stdexcept>
#include <vector>

#include <box2d/box2d.h>
#include <chipmunk/chipmunk.h>

#include "tamias2d/shape_def.hpp"
#include "tamias2d/world.hpp"

namespace tamias_bench {

std::string_view engine_name(EngineId e) {
    switch (e) {
    case EngineId::tamias:
        return "Tamias2D";
    case EngineId::chipmunk:
        return "Chipmunk 7";
    case EngineId::box2d:
        return "Box2D 2.4";
    case EngineId::box2d_v3_sse2:
        return "Box2D v3 SSE2";
    case EngineId::box2d_v3_avx2:
        return "Box2D v3 AVX2";
    }
    return "?";
}

namespace {

double box_area(const BodyDesc& b) {
    double a = 0.0;
    for (const BoxPart& p : b.boxes)
        a += 4.0 * p.hx * p.hy;
    return a;
}

/// The four corners of a box part in the body frame, counter-clockwise.
void corners(const BoxPart& p, V2 out[4]) {
    const double c = std::cos(p.angle), s = std::sin(p.angle);
    const double lx[4] = {-p.hx, p.hx, p.hx, -p.hx};
    const double ly[4] = {-p.hy, -p.hy, p.hy, p.hy};
    for (int i = 0; i < 4; ++i) {
        out[i] = {p.center.x + c * lx[i] - s * ly[i], p.center.y + s * lx[i] + c * ly[i]};
    }
}

// ---------------------------------------------------------------------------------- Tamias2D
class TamiasEngine final : public Engine {
  public:
    explicit TamiasEngine(const SceneDesc& s, int workers = 1, double manifold_reuse = -1.0,
                          int regions = 1, int substeps = 0)
        : dt_(s.dt), world_(world_def(s, workers, manifold_reuse, regions, substeps)) {
        ids_.reserve(s.bodies.size());
        for (const BodyDesc& d : s.bodies) {
            tamias2d::BodyDef bd;
            bd.type = d.dynamic ? tamias2d::BodyType::dynamic : tamias2d::BodyType::static_body;
            bd.position = {d.position.x, d.position.y};
            bd.angle = d.angle;
            bd.linear_velocity = {d.velocity.x, d.velocity.y};
            if (d.dynamic && d.boxes.empty()) {
                bd.mass = d.mass;
                bd.inertia = d.inertia;
            }
            const tamias2d::BodyId id = world_.create_body(bd);
            const tamias2d::Material m{d.density, d.restitution, d.friction};
            for (const BoxPart& p : d.boxes) {
                world_.create_shape(id, tamias2d::box_shape(2.0 * p.hx, 2.0 * p.hy, m,
                                                            {p.center.x, p.center.y}, p.angle));
            }
            ids_.push_back(id);
        }
        for (const JointDesc& j : s.joints) {
            tamias2d::RevoluteJointDef jd;
            jd.body_a = ids_[std::size_t(j.a)];
            jd.body_b = ids_[std::size_t(j.b)];
            jd.anchor = {j.anchor.x, j.anchor.y};
            world_.create_joint(jd);
        }
    }
    void step() override { world_.step(dt_); }
    Probe probe(int i) const override {
        const tamias2d::BodyId id = ids_[std::size_t(i)];
        const tamias2d::Vec2d p = world_.origin(id), v = world_.velocity(id);
        return {{p.x, p.y}, {v.x, v.y}, world_.angular_velocity(id), world_.orientation(id)};
    }
    std::uint64_t state_hash() const override { return world_.state_hash(); }
    QueryTimes timed_queries(const QueryLoad& load) override {
        QueryTimes t;
        const tamias2d::QueryFilter all{};
        const double r0 = cpu_ms();
        for (const Cast& c : load.rays)
            t.ray_hits +=
                world_.ray_cast({c.origin.x, c.origin.y}, {c.translation.x, c.translation.y}, all)
                    .has_value();
        const double r1 = cpu_ms();
        const tamias2d::Geometry disc = tamias2d::circle_shape(cast_radius).geometry;
        const tamias2d::Geometry square =
            tamias2d::box_shape(2.0 * cast_half_side, 2.0 * cast_half_side).geometry;
        for (std::size_t i = 0; i < load.casts.size(); ++i) {
            const Cast& c = load.casts[i];
            t.cast_hits += world_
                               .shape_cast(i % 2 == 0 ? disc : square, {c.origin.x, c.origin.y},
                                           0.0, {c.translation.x, c.translation.y}, all)
                               .has_value();
        }
        const double r2 = cpu_ms();
        t.ray_ms = r1 - r0;
        t.cast_ms = r2 - r1;
        return t;
    }

  private:
    static tamias2d::WorldDef world_def(const SceneDesc& s, int workers, double manifold_reuse,
                                        int regions, int substeps) {
        tamias2d::WorldDef def;
        if (substeps > 0) // the work-precision sweep; otherwise the default
            def.substeps = substeps;
        def.workers = workers;     // 1 in the peer benchmark: every engine on one thread
        if (manifold_reuse >= 0.0) // tamias_thread_bench's A/B; otherwise the default
            def.manifold_reuse_distance = manifold_reuse;
        def.contact_regions = regions;
        def.gravity = {s.gravity.x, s.gravity.y};
        def.enable_sleep = s.sleep; // time_to_sleep 0.5 s by default
        return def;
    }
    double dt_;
    tamias2d::World world_;
    std::vector<tamias2d::BodyId> ids_;
};

// ------------------------------------------------------------------------------ Chipmunk 7
class ChipmunkEngine final : public Engine {
  public:
    explicit ChipmunkEngine(const SceneDesc& s, int iterations = 0)
        : dt_(s.dt), space_(cpSpaceNew()) {
        cpSpaceSetIterations(space_, iterations > 0 ? iterations : 10);
        cpSpaceSetGravity(space_, cpv(s.gravity.x, s.gravity.y));
        // Sleeping is off by default (sleep time threshold INFINITY); slop and bias as shipped.
        if (s.sleep)
            cpSpaceSetSleepTimeThreshold(space_, 0.5);
        bodies_.reserve(s.bodies.size());
        for (const BodyDesc& d : s.bodies) {
            cpBody* body = nullptr;
            if (d.dynamic && d.boxes.empty()) {
                body = cpSpaceAddBody(space_, cpBodyNew(d.mass, d.inertia));
                cpBodySetPosition(body, cpv(d.position.x, d.position.y));
                cpBodySetAngle(body, d.angle);
                cpBodySetVelocity(body, cpv(d.velocity.x, d.velocity.y));
            } else if (d.dynamic) {
                if (d.boxes.size() != 1 || d.boxes[0].center.x != 0.0 ||
                    d.boxes[0].center.y != 0.0 || d.boxes[0].angle != 0.0) {
                    throw std::invalid_argument("Chipmunk adapter: dynamic bodies must be one "
                                                "centred box");
                }
                const double m = d.density * box_area(d);
                const double w = 2.0 * d.boxes[0].hx, h = 2.0 * d.boxes[0].hy;
                body = cpSpaceAddBody(space_, cpBodyNew(m, cpMomentForBox(m, w, h)));
                cpBodySetPosition(body, cpv(d.position.x, d.position.y));
                cpBodySetAngle(body, d.angle);
                cpBodySetVelocity(body, cpv(d.velocity.x, d.velocity.y));
                add_shape(cpBoxShapeNew(body, w, h, 0.0), d);
            } else {
                body = cpSpaceAddBody(space_, cpBodyNewStatic());
                cpBodySetPosition(body, cpv(d.position.x, d.position.y));
                cpBodySetAngle(body, d.angle);
                for (const BoxPart& p : d.boxes) {
                    V2 c[4];
                    corners(p, c);
                    const cpVect verts[4] = {cpv(c[0].x, c[0].y), cpv(c[1].x, c[1].y),
                                             cpv(c[2].x, c[2].y), cpv(c[3].x, c[3].y)};
                    add_shape(cpPolyShapeNew(body, 4, verts, cpTransformIdentity, 0.0), d);
                }
            }
            bodies_.push_back(body);
        }
        for (const JointDesc& j : s.joints) {
            constraints_.push_back(cpSpaceAddConstraint(
                space_, cpPivotJointNew(bodies_[std::size_t(j.a)], bodies_[std::size_t(j.b)],
                                        cpv(j.anchor.x, j.anchor.y))));
        }
    }
    ~ChipmunkEngine() override {
        // The space first, then what was in it: cpSpaceFree only reads the bodies (to wake
        // them), and removing shapes one by one filters every cached arbiter for each shape,
        // which takes 11 s for many_pyramids' 22000 boxes (never timed, but the job waits).
        cpSpaceFree(space_);
        for (cpConstraint* c : constraints_)
            cpConstraintFree(c);
        for (cpShape* sh : shapes_)
            cpShapeFree(sh);
        for (cpBody* b : bodies_)
            cpBodyFree(b);
    }
    ChipmunkEngine(const ChipmunkEngine&) = delete;
    ChipmunkEngine& operator=(const ChipmunkEngine&) = delete;

    void step() override { cpSpaceStep(space_, dt_); }
    Probe probe(int i) const override {
        const cpBody* b = bodies_[std::size_t(i)];
        const cpVect p = cpBodyGetPosition(b), v = cpBodyGetVelocity(b);
        return {{p.x, p.y}, {v.x, v.y}, cpBodyGetAngularVelocity(b), cpBodyGetAngle(b)};
    }

  private:
    void add_shape(cpShape* sh, const BodyDesc& d) {
        // Chipmunk multiplies the two shapes' coefficients: sqrt on each gives the pair's value.
        cpShapeSetFriction(sh, std::sqrt(d.friction));
        cpShapeSetElasticity(sh, std::sqrt(d.restitution));
        cpSpaceAddShape(space_, sh);
        shapes_.push_back(sh);
    }
    double dt_;
    cpSpace* space_;
    std::vector<cpBody*> bodies_;
    std::vector<cpShape*> shapes_;
    std::vector<cpConstraint*> constraints_;
};

// -------------------------------------------------------------------------------- Box2D 2.4
float f32(double x) {
    return static_cast<float>(x);
}

class Box2DEngine final : public Engine {
  public:
    explicit Box2DEngine(const SceneDesc& s, int velocity_iterations = 0,
                         int position_iterations = 0)
        : dt_(f32(s.dt)), velocity_iterations_(velocity_iterations > 0 ? velocity_iterations : 8),
          position_iterations_(position_iterations > 0 ? position_iterations : 3),
          world_(b2Vec2(f32(s.gravity.x), f32(s.gravity.y))) {
        world_.SetAllowSleeping(s.sleep); // b2_timeToSleep is 0.5 s
        bodies_.reserve(s.bodies.size());
        for (const BodyDesc& d : s.bodies) {
            b2BodyDef bd;
            bd.type = d.dynamic ? b2_dynamicBody : b2_staticBody;
            bd.position.Set(f32(d.position.x), f32(d.position.y));
            bd.angle = f32(d.angle);
            bd.linearVelocity.Set(f32(d.velocity.x), f32(d.velocity.y));
            bd.allowSleep = false;
            b2Body* body = world_.CreateBody(&bd);
            for (const BoxPart& p : d.boxes) {
                b2PolygonShape shape;
                shape.SetAsBox(f32(p.hx), f32(p.hy), b2Vec2(f32(p.center.x), f32(p.center.y)),
                               f32(p.angle));
                b2FixtureDef fd;
                fd.shape = &shape;
                fd.density = f32(d.density);
                fd.friction = f32(d.friction);       // Box2D: sqrt(f1 f2)
                fd.restitution = f32(d.restitution); // Box2D: max(e1, e2)
                body->CreateFixture(&fd);
            }
            if (d.dynamic && d.boxes.empty()) {
                b2MassData md;
                md.mass = f32(d.mass);
                md.center.SetZero();
                md.I = f32(d.inertia); // about the origin, which is the centre of mass here
                body->SetMassData(&md);
            }
            bodies_.push_back(body);
        }
        for (const JointDesc& j : s.joints) {
            b2RevoluteJointDef jd; // collideConnected false, no limit, no motor
            jd.Initialize(bodies_[std::size_t(j.a)], bodies_[std::size_t(j.b)],
                          b2Vec2(f32(j.anchor.x), f32(j.anchor.y)));
            world_.CreateJoint(&jd);
        }
    }
    void step() override { world_.Step(dt_, velocity_iterations_, position_iterations_); }
    Probe probe(int i) const override {
        const b2Body* b = bodies_[std::size_t(i)];
        const b2Vec2 p = b->GetPosition(), v = b->GetLinearVelocity();
        return {{p.x, p.y}, {v.x, v.y}, b->GetAngularVelocity(), b->GetAngle()};
    }

  private:
    float dt_;
    int velocity_iterations_, position_iterations_;
    b2World world_;
    std::vector<b2Body*> bodies_;
};

} // namespace

std::unique_ptr<Engine> make_tamias_engine(const SceneDesc& scene, int workers,
                                           double manifold_reuse, int regions) {
    return std::make_unique<TamiasEngine>(scene, workers, manifold_reuse, regions);
}

std::unique_ptr<Engine> make_engine(EngineId id, const SceneDesc& scene, const SolverKnobs& knobs) {
    switch (id) {
    case EngineId::tamias:
        return std::make_unique<TamiasEngine>(scene, 1, -1.0, 1, knobs.substeps);
    case EngineId::chipmunk:
        return std::make_unique<ChipmunkEngine>(scene, knobs.iterations);
    case EngineId::box2d:
        return std::make_unique<Box2DEngine>(scene, knobs.iterations, knobs.position_iterations);
    case EngineId::box2d_v3_sse2:
    case EngineId::box2d_v3_avx2:
        break; // in a worker process: remote_engine.hpp
    }
    throw std::invalid_argument("engine not in this process: " + std::string(engine_name(id)));
}

} // namespace tamias_bench
