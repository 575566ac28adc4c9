// Without exceptions (compiled with -fno-exceptions, or configured TAMIAS2D_EXCEPTIONS=OFF) the
// throwing forms are not declared: a game cannot call one by mistake. Its correct form (a
// `try_` call) must compile; under TAMIAS_WRONG_FORM the throwing form must not.
// Oracle: the compiler: World has no member create_body when TAMIAS2D_EXCEPTIONS is 0.
#include "tamias2d/shape_def.hpp"
#include "tamias2d/world.hpp"

#if TAMIAS2D_EXCEPTIONS
#error "compiled as a game without exceptions: TAMIAS2D_EXCEPTIONS must be 0"
#endif

bool add_ball(tamias2d::World& world) {
    const tamias2d::BodyDef def;
#ifdef TAMIAS_WRONG_FORM
    const tamias2d::BodyId ball = world.create_body(def);
    return world.is_valid(ball);
#else
    const tamias2d::Result<tamias2d::BodyId> ball = world.try_create_body(def);
    return ball.has_value();
#endif
}
