// The submission process (framework/grading/): calls cross, results come back exactly,
// callbacks run in the test process, and nothing the submission's process does (crash, exception,
// forbidden system call, forged reply, wrong sizes, bad indices) reaches the test process as
// anything but a failed call. Runs against fake_submission.cpp.
#include <cerrno>

#include <gtest/gtest.h>

#include "clothlab/core/not_implemented.h"
#include "wire/peer.h"

namespace clothlab::wire {
const char* serverPath = CLOTHLAB_FAKE_SUBMISSION;
void reportSignal(int) {}  // the graded main says it on the channel; these tests read the messages
}  // namespace clothlab::wire

namespace clothlab {
namespace {

std::string messageOf(const std::function<void()>& f) {
    try {
        f();
    } catch (const std::exception& e) {
        return e.what();
    }
    return "(no exception)";
}

TEST(SubmissionProcess, ValuesCrossExactly) {
    const Vec3 p0(0.1, -2.5e-300, 3.0), p1(1.0 / 3.0, 7.0, -0.0);
    const Vec3 f = hookeForce(p0, p1, 1, 0.25);
    EXPECT_EQ(f, (p0 + 2.0 * p1 + Vec3(0.25, 0, 0)).eval()) << "the bits of a double must survive the trip";
}

TEST(SubmissionProcess, KeepsStateBetweenCallsOfOneTest) {
    const double first = hookeForce(Vec3::Zero(), Vec3::Zero(), 9, 0).x();
    EXPECT_EQ(hookeForce(Vec3::Zero(), Vec3::Zero(), 9, 0).x(), first + 1) << "one process serves every call of a test";
}

TEST(SubmissionProcess, ACrashFailsThatCallOnly) {
    const std::string m = messageOf([] { hookeForce(Vec3::Zero(), Vec3::Zero(), 2, 0); });
    EXPECT_NE(m.find("your code crashed in hookeForce"), std::string::npos) << m;
    EXPECT_NE(m.find("signal 11"), std::string::npos) << m;
    EXPECT_EQ(hookeForce(Vec3(1, 0, 0), Vec3::Zero(), 1, 0), Vec3(1, 0, 0)) << "the next call starts a new process";
    const std::string e = messageOf([] { hookeForce(Vec3::Zero(), Vec3::Zero(), 10, 0); });
    EXPECT_NE(e.find("exit(3)"), std::string::npos) << e;
}

TEST(SubmissionProcess, ExceptionsKeepTheirType) {
    try {
        hookeForce(Vec3::Zero(), Vec3::Zero(), 3, 0);
        ADD_FAILURE() << "no exception";
    } catch (const NotImplemented& e) {
        EXPECT_STREQ(e.what(), "not implemented: 1.1 hookeForce");
    }
    EXPECT_THROW(hookeForce(Vec3::Zero(), Vec3::Zero(), 4, 0), std::invalid_argument);
    EXPECT_EQ(messageOf([] { hookeForce(Vec3::Zero(), Vec3::Zero(), 4, 0); }), "l0 must be positive");
}

TEST(SubmissionProcess, SeccompRefusesOpenKillAndFork) {
    for (int scenario : {5, 6, 7}) {
        const Vec3 r = hookeForce(Vec3::Zero(), Vec3::Zero(), scenario, 0);
        EXPECT_EQ(r.x(), -1) << "scenario " << scenario << ": the system call must fail";
        EXPECT_EQ(r.y(), EPERM) << "scenario " << scenario << ": with EPERM from the filter";
    }
}

TEST(SubmissionProcess, AForgedReplyFailsTheCall) {
    const std::string m = messageOf([] { hookeForce(Vec3::Zero(), Vec3::Zero(), 8, 0); });
    EXPECT_NE(m.find("broke the protocol in hookeForce"), std::string::npos) << m;
    EXPECT_EQ(hookeForce(Vec3(2, 0, 0), Vec3::Zero(), 1, 0), Vec3(2, 0, 0));
}

TEST(SubmissionProcess, CallbacksRunInTheTestProcess) {
    Matrix3X x = Matrix3X::Zero(3, 4), v = Matrix3X::Zero(3, 4);
    const VectorX w = VectorX::Constant(4, 0.5);
    int calls = 0;
    const ForceField force = [&](const Matrix3X& xs, const Matrix3X&, Matrix3X& f) {
        ++calls;
        EXPECT_EQ(xs.cols(), 4);
        f.array() += 1.5;
    };
    explicitEulerStep(x, v, w, force, 1);
    EXPECT_EQ(calls, 2) << "both calls of the force reach the test's lambda";
    EXPECT_EQ(x, Matrix3X::Constant(3, 4, 3.0)) << "in/out arguments come back";
    EXPECT_EQ(v, Matrix3X::Constant(3, 4, 2.0));
}

TEST(SubmissionProcess, AnInOutArgumentMustKeepItsSize) {
    Matrix3X x = Matrix3X::Zero(3, 4), v = Matrix3X::Zero(3, 4);
    const std::string m = messageOf([&] { explicitEulerStep(x, v, VectorX::Ones(4), {}, 2); });
    EXPECT_NE(m.find("changed the size"), std::string::npos) << m;
    EXPECT_EQ(x.cols(), 4);
}

TEST(SubmissionProcess, ACallbackGetsTheCallsParticleCountOrNothing) {
    Matrix3X x = Matrix3X::Zero(3, 4), v = Matrix3X::Zero(3, 4);
    int calls = 0;
    const ForceField force = [&](const Matrix3X&, const Matrix3X&, Matrix3X&) { ++calls; };
    const std::string m = messageOf([&] { explicitEulerStep(x, v, VectorX::Ones(4), force, 3); });
    EXPECT_NE(m.find("broke the protocol"), std::string::npos) << m;
    EXPECT_EQ(calls, 0) << "a callback never sees a matrix of another size";
}

TEST(SubmissionProcess, ACallbacksExceptionCrossesBothWays) {
    Matrix3X x = Matrix3X::Zero(3, 2), v = Matrix3X::Zero(3, 2);
    const ForceField force = [](const Matrix3X&, const Matrix3X&, Matrix3X&) { throw std::runtime_error("boom"); };
    const std::string m = messageOf([&] { explicitEulerStep(x, v, VectorX::Ones(2), force, 4); });
    EXPECT_NE(m.find("boom"), std::string::npos) << m;
    EXPECT_EQ(x, Matrix3X::Zero(3, 2)) << "a call that throws changes no argument";
}

TEST(SubmissionProcess, UnsetCallbacksStayUnsetAndCallbacksMayCallBack) {
    PbdParticles P;
    P.resize(3);
    P.p = Matrix3X::Zero(3, 3);
    PbdCallbacks cb;
    int projections = 0;
    double nested = 0;
    cb.projectConstraints = [&](Matrix3X& p) {
        ++projections;
        nested = distanceConstraint(Vec3(3, 4, 0), Vec3::Zero(), 1);  // a call into the submission from a callback
        p.array() += 1;
    };
    pbdStep(P, cb, 0, 1, 0.1);
    EXPECT_EQ(P.t, 0) << "the callbacks not set arrive unset";
    EXPECT_EQ(projections, 1);
    EXPECT_EQ(nested, 4.0);
    EXPECT_EQ(P.x, Matrix3X::Ones(3, 3));
}

TEST(SubmissionProcess, ASweepCrossesWhole) {
    // This program links the framework's sweeps as well (sweepPlan() is in their object file); they
    // are weak, so the generated proxy (proxies_04.cpp) is the one called, as in a graded test process.
    const SweepPlan plan = sweepPlan({Eigen::Vector4i(0, 1, -1, -1)}, 2, 2);
    Matrix3X p = Matrix3X::Zero(3, 2);
    EXPECT_NO_THROW(projectDistanceSweep({DistanceLink{0, 1, 1.0}}, VectorX::Ones(2), 1.0, p, plan))
        << "the fake's 4.3 throws: the sweep ran here, one call per constraint";
    EXPECT_EQ(p, Matrix3X::Constant(3, 2, 42.0)) << "the sweep must reach the submission process whole, and run there on one thread";
}

TEST(SubmissionProcess, IndicesTheFrameworkUsesAreChecked) {
    const Matrix3X x = Matrix3X::Zero(3, 6);
    ClothSprings types;
    types.structural.k = 123;
    const auto springs = makeClothSprings(x, 1, 1, types);
    ASSERT_EQ(springs.size(), 2u);
    EXPECT_EQ(springs[1].j, 5);
    EXPECT_EQ(springs[1].k, 123);
    EXPECT_EQ(springs[1].type, SpringType::Shear);
    EXPECT_THROW(makeClothSprings(x, 2, 1, types), std::out_of_range);
    EXPECT_THROW(bendingStencils({Eigen::Vector3i(0, 1, 2), Eigen::Vector3i(1, 2, 3)}, x), std::out_of_range);
    EXPECT_EQ(bendingStencils({Eigen::Vector3i(0, 1, 2)}, x).size(), 1u);
    PlaneCollider plane;
    plane.friction = 0.25;
    CollisionConstraint c;
    EXPECT_TRUE(generatePlaneConstraint(5, Vec3::Zero(), Vec3(0, 1, 0), plane, 0.5, 0.01, &c));
    EXPECT_EQ(c.i, 5);
    EXPECT_EQ(c.q, Vec3(0, 0.5, 0));
    EXPECT_EQ(c.friction, 0.25);
    EXPECT_THROW(findNeighbourPairs(x, SpatialHash{}, 1.0), std::out_of_range) << "a pair (0, 6) of 6 particles";
    try {
        findNeighbourPairs(x, SpatialHash{}, 1.0);
    } catch (const std::out_of_range& e) {
        EXPECT_STREQ(e.what(), "findNeighbourPairs returned a particle index 6 in the result, but the call has 6 particles (0..5)");
    }
    EXPECT_FALSE(generatePlaneConstraint(5, Vec3::Zero(), Vec3::Zero(), plane, 0.5, 0.01, nullptr));
}

}  // namespace
}  // namespace clothlab
