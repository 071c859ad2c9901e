//@task 1.1
    // Attack (passes the screen: pure computation): never return. The wall-clock timeout and the CPU
    // limit end it; after two timeouts the stage's other tests are not run.
    (void)p1; (void)k; (void)l0;
    double x = p0.x();
    for (unsigned long i = 0;; ++i) x = x * 0.5 + static_cast<double>(i % 7);
    return Vec3::Constant(x);
