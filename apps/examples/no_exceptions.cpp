// A small game loop without exceptions: the game is compiled with -fno-exceptions and uses the
// error-returning `try_` forms (docs/user-guide.md, "Without exceptions"). A ball is dropped on
// the ground and a bad shape is refused with an Error instead of an exception.
#include <cstdio>

#include "tamias2d/shape_def.hpp"
#include "tamias2d/world.hpp"

namespace {
/// The game's way of reporting: print the error and carry on.
void report(const char* what, const tamias2d::Error& error) {
    std::printf("%s refused (%s): %s\n", what, tamias2d::to_string(error.kind),
                error.message.c_str());
}
} // namespace

int main() {
    using namespace tamias2d;
    WorldDef settings;
    settings.gravity = {0.0, -10.0}; // m/s^2
    Result<World> made = World::try_create(settings);
    if (!made) {
        report("world", made.error());
        return 1;
    }
    World world = std::move(made).value();

    BodyDef ground_def;
    ground_def.type = BodyType::static_body;
    const Result<BodyId> ground = world.try_create_body(ground_def);
    const Result<ShapeDef> floor = try_box_shape(20.0, 1.0);
    if (!ground || !floor || !world.try_create_shape(*ground, *floor))
        return 1;

    BodyDef ball_def;
    ball_def.position = {0.0, 5.0};
    const Result<BodyId> ball = world.try_create_body(ball_def);
    if (!ball)
        return 1;
    // A mistake a level file could hold: a radius of -0.5 m. Refused, the world unchanged.
    const Result<ShapeDef> bad = try_circle_shape(-0.5);
    if (!bad)
        report("circle_shape(-0.5)", bad.error());
    if (const Result<ShapeDef> ok = try_circle_shape(0.5);
        !ok || !world.try_create_shape(*ball, *ok))
        return 1;

    for (int frame = 1; frame <= 120; ++frame) { // two seconds at 60 Hz
        if (const Result<void> stepped = world.try_step(1.0 / 60.0); !stepped) {
            report("step", stepped.error());
            return 1;
        }
        if (frame % 30 != 0)
            continue;
        const Result<Vec2d> p = world.try_position(*ball);
        if (!p)
            return 1;
        std::printf("t=%.2f ball y=%.3f\n", world.try_time().value_or(0.0), p->y);
    }
    // A handle of a destroyed body: an Error, not a crash and not an exception.
    if (!world.try_destroy_body(*ball))
        return 1;
    if (const Result<Vec2d> gone = world.try_position(*ball); !gone)
        report("position of a destroyed body", gone.error());
    return 0;
}
