// World's contact_hooks calls: the pre-solve callback and the material mixing functions (DD42)
// with the shapes' user material ids. The work is the contact manager's (its contact_hooks
// block); each call here checks its input first, so a refusal changes nothing.
#include <cstdint>
#include <utility>

#include "tamias2d/world.hpp"
#include "tamias2d/world_impl.hpp"

namespace tamias2d {

void World::set_pre_solve(PreSolveFunction callback) {
    impl_->contacts.pre_solve = std::move(callback);
}

void World::set_friction_mixing(MaterialMixFunction mix) {
    Impl& w = *impl_;
    w.contacts.remix(w.shapes, w.bodies, std::move(mix), w.contacts.restitution_mixing);
}

void World::set_restitution_mixing(MaterialMixFunction mix) {
    Impl& w = *impl_;
    w.contacts.remix(w.shapes, w.bodies, w.contacts.friction_mixing, std::move(mix));
}

void World::set_user_material(ShapeId id, std::uint64_t material_id) {
    Impl& w = *impl_;
    const Shape& sh = w.shapes.get(id);
    Material m = w.shapes.defs[id.index].material;
    if (m.user_material_id == material_id)
        return;
    m.user_material_id = material_id;
    w.contacts.rematerial(id.index, w.shapes, m); // \srs{DD42}
    // As a changed friction: the body and, with sleeping, the bodies touching it feel it.
    w.bodies.wake(sh.body);
    if (w.def.enable_sleep)
        w.contacts.wake_touching(sh.body, w.bodies);
}

std::uint64_t World::user_material(ShapeId id) const {
    impl_->shapes.get(id);
    return impl_->shapes.defs[id.index].material.user_material_id;
}

} // namespace tamias2d
