//@task 1.1
    // Attack (passes the screen): unbounded recursion until the stack overflows (a crash).
    if (k > -1.0) return hookeForce(p1, p0, k + 1.0, l0) + hookeForce(p0, p1, k + 2.0, l0);
    return Vec3::Zero();
