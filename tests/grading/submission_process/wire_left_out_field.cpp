// Must not compile (test grade.wire_refuses_a_left_out_field): CLOTHLAB_WIRE lists two of the three
// fields of Probe, so the third would silently not cross between the two processes.
#include "wire/wire.h"

namespace probe {
struct Probe {
    int a = 0;
    double b = 0.0;
    clothlab::Vec3 c{0, 0, 0};
};
CLOTHLAB_WIRE(Probe, a, b)
}  // namespace probe
