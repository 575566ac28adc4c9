// The rain scene's deepest contact penetration over its first 600 steps (10 s), with continuous
// collision off, on (the default, against static shapes), and with the falling boxes marked
// bullets (all of them, and every other one). Prints one line per setting; docs/verification.md
// (O3) quotes the figures. Not a timing: run it from any build.
#include <cmath>
#include <cstdio>
#include <vector>

#include "tamias2d/io/scene_generators.hpp"
#include "tamias2d/world.hpp"

using namespace tamias2d;

namespace {

struct Deepest {
    double separation = 0.0; ///< m, the most negative contact separation seen
    int step = 0;
    int escaped = 0; ///< boxes outside the container at the end
};

Deepest run(bool continuous, int bullet_every) {
    WorldDef def;
    def.enable_continuous = continuous;
    World world(def);
    io::RainParams p;
    int n = 0;
    std::vector<BodyId> boxes;
    for (io::SceneBody& b : io::generate_rain(p)) {
        if (b.def.type == BodyType::dynamic) {
            b.def.bullet = bullet_every > 0 && n % bullet_every == 0;
            ++n;
        }
        const BodyId id = world.create_body(b.def);
        for (const ShapeDef& s : b.shapes)
            world.create_shape(id, s);
        if (b.def.type == BodyType::dynamic)
            boxes.push_back(id);
    }
    Deepest out;
    for (int k = 1; k <= 600; ++k) {
        world.step(1.0 / 60.0);
        for (const ContactInfo& c : world.contacts())
            for (int i = 0; i < c.point_count; ++i)
                if (c.points[i].separation < out.separation) {
                    out.separation = c.points[i].separation;
                    out.step = k;
                }
    }
    const double half = 0.5 * p.container.width;
    for (const BodyId b : boxes) {
        const Vec2d x = world.position(b);
        out.escaped += std::abs(x.x - p.container.origin.x) > half || x.y < p.container.origin.y;
    }
    return out;
}

} // namespace

int main() {
    const struct {
        const char* name;
        bool continuous;
        int bullet_every;
    } settings[] = {{"continuous collision off", false, 0},
                    {"continuous collision on (default)", true, 0},
                    {"on, every box a bullet", true, 1},
                    {"on, every other box a bullet", true, 2}};
    std::printf("rain (2000 boxes of 0.5 m, 600 steps of 1/60 s): deepest contact penetration\n");
    for (const auto& s : settings) {
        const Deepest d = run(s.continuous, s.bullet_every);
        std::printf("  %-36s %.4f m (step %d), %d boxes outside the container\n", s.name,
                    -d.separation, d.step, d.escaped);
    }
    return 0;
}
