// The World's identity calls: user data on the world, its bodies, shapes and joints, and the
// ways from a shape to its body, from a body to its shapes' boxes, joints and contacts, and from
// a joint to its bodies and kind. None changes the simulation.
#include <algorithm>

#include "tamias2d/world.hpp"
#include "tamias2d/world_impl.hpp"

namespace tamias2d {

void World::set_user_data(UserData data) {
    impl_->def.user_data = data;
}
UserData World::user_data() const {
    return impl_->def.user_data;
}

void World::set_user_data(BodyId id, UserData data) {
    impl_->bodies.get_for_attach(id); // handle check (no mass to settle)
    impl_->bodies.settings[id.index].user_data = data;
}
UserData World::user_data(BodyId id) const {
    impl_->bodies.get_for_attach(id); // handle check
    return impl_->bodies.settings[id.index].user_data;
}

void World::set_user_data(ShapeId id, UserData data) {
    impl_->shapes.get(id);
    impl_->shapes.defs[id.index].user_data = data;
}
UserData World::user_data(ShapeId id) const {
    impl_->shapes.get(id);
    return impl_->shapes.defs[id.index].user_data;
}

void World::set_user_data(JointId id, UserData data) {
    impl_->joints.get(id).user_data = data;
}
UserData World::user_data(JointId id) const {
    return impl_->joints.get(id).user_data;
}

BodyId World::body(ShapeId id) const {
    return impl_->bodies.id(impl_->shapes.get(id).body);
}

ShapeType World::shape_type(ShapeId id) const {
    impl_->shapes.get(id);
    return impl_->shapes.defs[id.index].geometry.type;
}

Geometry World::geometry(ShapeId id) const {
    impl_->shapes.get(id);
    return impl_->shapes.defs[id.index].geometry;
}

Aabb World::shape_aabb(ShapeId id) const {
    const Shape& s = impl_->shapes.get(id);
    return impl_->shapes.box(s, impl_->bodies.bodies[s.body]);
}

Aabb World::body_aabb(BodyId id) const {
    const Body& b = impl_->bodies.get(id);
    const ShapeStore& shapes = impl_->shapes;
    if (b.first_shape == null_index)
        return {b.xf.p.x, b.xf.p.y, b.xf.p.x, b.xf.p.y};
    Aabb box = shapes.box(shapes.shapes[b.first_shape], b);
    for (std::uint32_t s = shapes.shapes[b.first_shape].next; s != null_index;
         s = shapes.shapes[s].next) {
        const Aabb more = shapes.box(shapes.shapes[s], b);
        box = {std::min(box.min_x, more.min_x), std::min(box.min_y, more.min_y),
               std::max(box.max_x, more.max_x), std::max(box.max_y, more.max_y)};
    }
    return box;
}

std::vector<JointId> World::joints(BodyId id) const {
    impl_->bodies.get(id); // handle check
    std::vector<JointId> out;
    for (const std::uint32_t j : impl_->joints.of_body(id.index))
        out.push_back(impl_->joints.id(j));
    return out;
}

std::vector<ContactInfo> World::contacts(BodyId id) const {
    impl_->bodies.get(id); // handle check
    std::vector<ContactInfo> out;
    for (const ContactInfo& c : contacts()) {
        if (c.body_a == id || c.body_b == id)
            out.push_back(c);
    }
    return out;
}

} // namespace tamias2d
