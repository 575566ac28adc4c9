#include "box2d_v3_engine.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include <box2d/box2d.h>

#include "joint_drift.hpp"
#include "thread_cpu_time.hpp"

namespace tamias_bench {

namespace {

float f32(double x) {
    return static_cast<float>(x);
}

b2Vec2 vec(V2 v) {
    return {f32(v.x), f32(v.y)};
}

/// The exact rotation (v3's b2MakeRot approximates the cosine and sine).
b2Rot rotation(double angle) {
    return {f32(std::cos(angle)), f32(std::sin(angle))};
}

class Box2DV3Engine final : public Engine {
  public:
    Box2DV3Engine(const SceneDesc& s, int workers, double recycle_distance, int substeps)
        : dt_(f32(s.dt)), substeps_(substeps > 0 ? substeps : 4) {
        b2WorldDef wd = b2DefaultWorldDef(); // contact 30 Hz, continuous collision on
        wd.gravity = vec(s.gravity);
        wd.enableSleep = s.sleep; // a body falls asleep after b2_timeToSleep, 0.5 s
        wd.workerCount = workers; // 1 in tamias_bench, as the other engines; above 1, v3's
                                  // own scheduler (no task callbacks given)
        world_ = b2CreateWorld(&wd);
        if (recycle_distance >= 0.0)
            b2World_SetContactRecycleDistance(world_, f32(recycle_distance));
        bodies_.reserve(s.bodies.size());
        for (const BodyDesc& d : s.bodies) {
            b2BodyDef bd = b2DefaultBodyDef();
            bd.type = d.dynamic ? b2_dynamicBody : b2_staticBody;
            bd.position = vec(d.position);
            bd.rotation = rotation(d.angle);
            bd.linearVelocity = vec(d.velocity);
            const b2BodyId body = b2CreateBody(world_, &bd);
            for (const BoxPart& p : d.boxes) {
                const b2Polygon box =
                    b2MakeOffsetBox(f32(p.hx), f32(p.hy), vec(p.center), rotation(p.angle));
                b2ShapeDef sd = b2DefaultShapeDef();
                sd.density = f32(d.density);
                sd.material.friction = f32(d.friction);       // v3: sqrt(f1 f2)
                sd.material.restitution = f32(d.restitution); // v3: max(e1, e2)
                b2CreatePolygonShape(body, &sd, &box);
            }
            if (d.dynamic && d.boxes.empty()) {
                // About the origin, which is the centre of mass here.
                b2Body_SetMassData(body, {f32(d.mass), {0.0f, 0.0f}, f32(d.inertia)});
            }
            bodies_.push_back(body);
        }
        const std::vector<LocalAnchors> anchors = local_anchors(s);
        for (std::size_t k = 0; k < s.joints.size(); ++k) {
            b2RevoluteJointDef jd = b2DefaultRevoluteJointDef(); // no limit, motor or spring
            jd.base.bodyIdA = bodies_[std::size_t(s.joints[k].a)];
            jd.base.bodyIdB = bodies_[std::size_t(s.joints[k].b)];
            jd.base.localFrameA.p = vec(anchors[k].on_a);
            jd.base.localFrameB.p = vec(anchors[k].on_b);
            b2CreateRevoluteJoint(world_, &jd);
        }
    }
    ~Box2DV3Engine() override { b2DestroyWorld(world_); }
    Box2DV3Engine(const Box2DV3Engine&) = delete;
    Box2DV3Engine& operator=(const Box2DV3Engine&) = delete;

    void step() override { b2World_Step(world_, dt_, substeps_); }
    Probe probe(int i) const override {
        const b2BodyId b = bodies_[std::size_t(i)];
        const b2Vec2 p = b2Body_GetPosition(b), v = b2Body_GetLinearVelocity(b);
        const b2Rot q = b2Body_GetRotation(b);
        // atan2 itself: v3's b2Rot_GetAngle approximates it, which would show as joint drift.
        return {{p.x, p.y}, {v.x, v.y}, b2Body_GetAngularVelocity(b), std::atan2(q.s, q.c)};
    }

    QueryTimes timed_queries(const QueryLoad& load) override {
        QueryTimes t;
        const b2QueryFilter all = b2DefaultQueryFilter();
        const double r0 = cpu_ms();
        for (const Cast& c : load.rays)
            t.ray_hits +=
                b2Shape_IsValid(
                    b2World_CastRayClosest(world_, pos(c.origin), vec(c.translation), all).shapeId)
                    ? 1
                    : 0;
        const double r1 = cpu_ms();
        const b2Vec2 centre{0.0f, 0.0f};
        const b2ShapeProxy disc = b2MakeProxy(&centre, 1, f32(cast_radius));
        const float h = f32(cast_half_side);
        const b2Vec2 corners[4] = {{-h, -h}, {h, -h}, {h, h}, {-h, h}};
        const b2ShapeProxy square = b2MakeProxy(corners, 4, 0.0f);
        for (std::size_t i = 0; i < load.casts.size(); ++i) {
            const Cast& c = load.casts[i];
            float closest = 2.0f; // the callback clips the cast at each hit: the closest stays
            b2World_CastShape(world_, pos(c.origin), i % 2 == 0 ? &disc : &square,
                              vec(c.translation), all, clip_at_hit, &closest);
            t.cast_hits += closest <= 1.0f ? 1 : 0;
        }
        const double r2 = cpu_ms();
        t.ray_ms = r1 - r0;
        t.cast_ms = r2 - r1;
        return t;
    }

  private:
    static b2Pos pos(V2 v) {
        b2Pos p;
        p.x = f32(v.x);
        p.y = f32(v.y);
        return p;
    }
    /// b2CastResultFcn: keeps the nearest fraction and clips the cast there.
    static float clip_at_hit(b2ShapeId, b2Pos, b2Vec2, float fraction, void* context) {
        float& closest = *static_cast<float*>(context);
        closest = std::min(closest, fraction);
        return fraction;
    }

    float dt_;
    int substeps_;
    b2WorldId world_{};
    std::vector<b2BodyId> bodies_;
};

} // namespace

std::unique_ptr<Engine> make_box2d_v3_engine(const SceneDesc& scene, int workers,
                                             double recycle_distance, int substeps) {
    return std::make_unique<Box2DV3Engine>(scene, workers, recycle_distance, substeps);
}

} // namespace tamias_bench
