// A test's own contacts in a ContactManager, whose arrays only its own calls write (the
// library adds contacts through the broad and narrow phases alone): the one friend of them.
#pragma once

#include "tamias2d/dynamics/contacts/contact_manager.hpp"

namespace tamias2d {

struct ContactManagerAccess {
    /// Appends contact `c` with accumulated impulses `warm`, its other records empty.
    static void add(ContactManager& m, const Contact& c, const ContactImpulses& warm) {
        m.contacts_.push_back(c);
        m.warm_impulses_.push_back(warm);
        m.total_impulses_.emplace_back();
        m.bases_.emplace_back();
        m.edge_inputs_.emplace_back();
    }
};

} // namespace tamias2d
