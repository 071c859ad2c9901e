//@head
#include <cstdio>
#include <vector>

//@task 1.1
    std::vector<std::vector<double>> hoard;
    for (;;) hoard.emplace_back(std::size_t(1) << 27, 1.0);  // 1 GiB at a time, touched
    return Vec3::Zero();
