// BENIGN FIXTURE: the stub with harmless student additions. It scores 0 (every task still
// throws NotImplemented) but a careful screen must ACCEPT it: nothing here is an attack.
//@head
#include <array>
#include <iostream>
#include <vector>


// Harmless student additions: std::sort with a lambda, std::map from the stub's includes, a helper.
namespace clothlab {
std::pair<int, int> sortedEdge(int a, int b) { return a < b ? std::make_pair(a, b) : std::make_pair(b, a); }
}  // namespace clothlab
//@each
    std::vector<int> order{3, 1, 2};
    std::sort(order.begin(), order.end(), [](int a, int b) { return a > b; });
    std::map<std::pair<int, int>, int> seen{{clothlab::sortedEdge(2, 1), order.front()}};
    std::cout << "debug: " << seen.size() << " edge(s)\n";
