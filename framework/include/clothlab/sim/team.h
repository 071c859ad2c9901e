/// @file team.h
/// @brief The threads of the solver's parallel loops (the colour groups of the PBD sweeps, the
/// collision runs, implicit Euler's particles), and how many of them the default `solver.threads: 0`
/// uses: as many as are faster, measured while the simulation runs.
///
/// Why measured: on an idle 2-core machine two threads take about half the time of one; beside
/// another busy process the second thread waits for a core at every colour group's end, and two
/// threads took up to 100 times longer than one (docs/performance.md, "Two cores that never hurt").
/// Which case holds is only known by timing it. The results never depend on the team size: every
/// parallel loop gives the same bits on any number of threads, so switching is free of side effects.
///
/// Why not OpenMP's threads: libgomp's waiting threads spin for milliseconds (it reads
/// OMP_WAIT_POLICY once, before main) and take the core another process needs; the helpers here
/// spin a few microseconds, then sleep.
#pragma once
#include <chrono>
#include <functional>

namespace clothlab {

/// How long a waiting thread (a helper between jobs, the caller at a job's end) checks for work
/// before it sleeps: long enough to bridge the gap between two colour groups, short enough not to
/// keep a core another process needs.
constexpr std::chrono::microseconds kTeamSpin{50};

/// Runs share(t, n) for t = 0 .. n − 1 at the same time, n = threads: share 0 on the calling thread,
/// share t on helper thread t of the calling thread (started at the first use, kept until the
/// calling thread ends). Returns when every share has returned. A share that throws: the first
/// exception caught is rethrown here after all shares ended. threads ≤ 1: share(0, 1) on the calling
/// thread, no helper is started.
/// @param threads  n, the team size
/// @param share    the work of thread t of n
void runShares(int threads, const std::function<void(int t, int n)>& share);

/// The team size that parallel loops asking for `threads` use on this thread now:
/// \f$ \max(1, \min(\mathit{threads}, \mathit{cap})) \f$ with the cap of the innermost TeamCap alive on
/// this thread (no TeamCap: no cap); inside a probe (AdaptiveTeam::Unit) also at most the probe's size,
/// or once the probe can no longer win the current size. Each call counts as one loop of the probe.
/// @param threads  the threads asked for (a SweepPlan's, solver.threads resolved)
/// @return         ≥ 1
int teamThreads(int threads);

/// Splits the items [0, count) into n = teamThreads(threads) contiguous shares,
/// share t = [⌊count·t/n⌋, ⌊count·(t+1)/n⌋), and calls each(begin, end) for every share at the same
/// time (runShares()); one call each(0, count) when n = 1 or count < minParallel.
/// @param count        number of items, ≥ 0
/// @param threads      the threads asked for
/// @param minParallel  the smallest count that is split
/// @param each         works on the items [begin, end) (items of different shares must be independent)
void forEachShare(int count, int threads, int minParallel, const std::function<void(int begin, int end)>& each);

/// While it lives, the parallel loops this thread starts use at most `most` threads (teamThreads());
/// nested caps take the smaller.
class TeamCap {
public:
    /// @param most  the cap, ≥ 1
    explicit TeamCap(int most);
    /// Restores the cap that was in force before this one.
    ~TeamCap();
    TeamCap(const TeamCap&) = delete;
    TeamCap& operator=(const TeamCap&) = delete;

private:
    int outer_;  ///< the cap before this one, restored at the end
};

/// What `solver.threads: 0` allows at most: setDefaultThreads()'s value if set, else OpenMP's
/// omp_get_max_threads() (OMP_NUM_THREADS if set, else every core).
/// @return ≥ 1
int defaultThreads();

/// Sets what defaultThreads() returns from now on, in this process (0: back to OpenMP's value).
/// For tests and for programs that share the machine in a known way.
/// @param threads  ≥ 0
void setDefaultThreads(int threads);

/// The clock that times AdaptiveTeam's units and probes: returns now.
using TeamClock = std::chrono::steady_clock::time_point (*)();

/// Sets the clock that times AdaptiveTeam's units and probes from now on, in this process (nullptr:
/// std::chrono::steady_clock::now, the default). For tests that drive a team with made-up times.
/// @param now  the clock, or nullptr
void setTeamClock(TeamClock now);

/// The team size of one solver: fixed (`solver.threads: N`, N ≥ 1) or, for the default
/// `solver.threads: 0`, chosen between 1 and m = defaultThreads() threads by timing.
///
/// The solver runs every unit of its work (a PBD step, an implicit Euler step: long enough to span
/// several of the scheduler's time slices) inside unit(), which caps its parallel loops at threads()
/// and records the unit's wall-clock time T. The rule:
/// - per size s ∈ {1, m} an exponential moving average \f$ \bar T_s \leftarrow \bar T_s + \tfrac14 (T - \bar T_s) \f$;
///   the first unit of each size (starting its threads, cold caches) is not counted;
/// - at the start each size runs until it has one counted unit (m first), then the size of the smaller
///   \f$ \bar T \f$ is current;
/// - every `interval` units of the current size one unit runs with the other size (a probe); its T
///   replaces the other's \f$ \bar T \f$. A probe that wins by the margin
///   (\f$ T < (1 - \mathit{kMargin})\,\bar T_{current} \f$) is followed by a second one; when that wins
///   too, its size becomes current and interval = kFirstInterval (one lucky unit, the neighbour
///   program pausing for a moment, does not switch the team); a probe that loses doubles interval, up
///   to kLongestInterval. A probe also comes at
///   once when \f$ (1 - \mathit{kMargin})\,\bar T_{current} \f$ rises above the other's
///   \f$ \bar T \f$ (the machine got busier or quieter).
///
/// A probe stops as soon as it can no longer win: once it has run for
/// \f$ (1 - \mathit{kMargin})\,\bar T_{current} \f$, the rest of its unit's parallel loops use the current
/// size, and its T is estimated as \f$ t_{cut} \cdot L / L_{probe} \f$ (t_cut: the time when the first
/// loop found the limit passed; L: the unit's loops; L_probe: those that ran with the probe's size).
/// So a probe costs at most about one unit of the current size, however slow the other size is (two
/// threads beside another busy program can take many times longer than one).
///
/// Once the interval has grown, probes that lose cost at most one unit in kLongestInterval; when the
/// load changes, the current size follows within kLongestInterval units.
class AdaptiveTeam {
public:
    static constexpr int kFirstInterval = 4;     ///< units between probes after a switch
    static constexpr int kLongestInterval = 64;  ///< the most units between probes
    static constexpr double kMargin = 0.05;      ///< how much faster the other size must be to switch

    /// @param requested  solver.threads: N ≥ 1 fixes the team at N threads, 0 chooses between 1 and
    ///                   defaultThreads() (fixed at 1 when that is 1)
    explicit AdaptiveTeam(int requested = 1);

    /// The size the next unit runs with.
    int threads() const { return adaptive_ ? size_[now_ ^ probing_] : size_[1]; }
    /// The most threads this team uses (solver.threads resolved: N, or defaultThreads() for 0).
    int most() const { return size_[1]; }
    /// True for `solver.threads: 0` with defaultThreads() ≥ 2: the size is chosen by timing.
    bool adaptive() const { return adaptive_; }
    /// Records that the unit just run with threads() took `seconds` and chooses the next unit's size
    /// (the rule in the class comment). Nothing for a fixed team.
    /// @param seconds  wall-clock time of the unit, s
    void record(double seconds);
    /// Units run (and recorded) with one thread (size 1) or with most() threads (any other size).
    /// @param size  1 or most()
    long units(int size) const { return units_[size == 1 ? 0 : 1]; }
    /// How often the current size changed.
    long switches() const { return switches_; }

    /// One unit of work: caps this thread's parallel loops at the team's threads() while it lives,
    /// then records its wall-clock time (record()); a probe that can no longer win goes on with the
    /// current size and records its estimated time (class comment).
    class Unit {
    public:
        /// @param team  the team that chooses the size and records the time
        explicit Unit(AdaptiveTeam& team);
        /// Ends the cap and records the unit's wall-clock time with AdaptiveTeam::record().
        ~Unit();
        Unit(const Unit&) = delete;
        Unit& operator=(const Unit&) = delete;

    private:
        AdaptiveTeam& team_;                          ///< where the time goes
        bool probe_;                                  ///< a probe that stops once it cannot win (class comment)
        TeamCap cap_;                                 ///< the size of this unit (of a probe: the larger size)
        std::chrono::steady_clock::time_point start_;  ///< when the unit began
    };
    /// Starts one unit (see Unit); keep the result alive for the unit's duration.
    Unit unit() { return Unit(*this); }

private:
    /// Starts a probe when one is due.
    void scheduleProbe();

    bool adaptive_ = false;   ///< chosen by timing
    int size_[2] = {1, 1};    ///< the two sizes: 1 and most()
    int now_ = 1;             ///< index of the current size (most() first)
    int probing_ = 0;         ///< 1: the next unit runs with the other size
    bool confirmed_ = false;  ///< the last probe won: the next one decides
    double mean_[2] = {0, 0}; ///< T̄ per size, s (valid once counted_ > 0)
    long counted_[2] = {0, 0};  ///< units counted per size
    long units_[2] = {0, 0};  ///< units recorded per size, the uncounted first ones too
    int interval_ = kFirstInterval;    ///< units of the current size between probes
    int untilProbe_ = kFirstInterval;  ///< units of the current size left before the next probe
    long switches_ = 0;       ///< changes of the current size
};

}  // namespace clothlab
