#include "clothlab/sim/team.h"

#ifndef CLOTHLAB_WEB
#include <omp.h>
#endif

#include <algorithm>
#include <atomic>
#include <climits>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <thread>
#include <utility>
#include <vector>

namespace clothlab {
namespace {
using Clock = std::chrono::steady_clock;
using Share = std::function<void(int t, int n)>;

/// Tells the core that this thread is waiting (lets the other hyperthread run).
inline void relax() {
#if defined(__x86_64__) || defined(__i386__)
    __builtin_ia32_pause();
#endif
}

/// The helper threads of one calling thread. A job is published by raising `generation`; helper t
/// runs share t of it (if t < n) and counts `pending` down; the caller runs share 0 and waits until
/// pending is 0. Every wait checks for kTeamSpin, then sleeps on the condition variable; a thread
/// that changes what others wait for wakes the sleepers (if any).
class Helpers {
public:
    ~Helpers() {
        stop_ = true;
        generation_.fetch_add(1);
        wake();
        for (std::thread& t : threads_) t.join();
    }

    void run(int n, const Share& share) {
        while (static_cast<int>(threads_.size()) < n - 1) {
            const int t = static_cast<int>(threads_.size()) + 1;
            const unsigned seen = generation_.load();
            threads_.emplace_back([this, t, seen] { serve(t, seen); });
        }
        job_ = &share;
        n_ = n;
        error_ = nullptr;
        pending_.store(static_cast<int>(threads_.size()));  // every helper reports, those with t ≥ n too
        generation_.fetch_add(1);                            // publishes job_, n_ (sequentially consistent)
        wake();
        try {
            share(0, n);
        } catch (...) {
            keep();
        }
        await([this] { return pending_.load() == 0; });
        if (error_) std::rethrow_exception(std::exchange(error_, nullptr));
    }

private:
    /// Helper t: waits for each new generation, runs its share, reports.
    void serve(int t, unsigned seen) {
        for (;;) {
            await([&] { return generation_.load() != seen; });
            seen = generation_.load();  // the caller raises it again only after every helper reported
            if (stop_) return;
            if (t < n_) {
                try {
                    (*job_)(t, n_);
                } catch (...) {
                    keep();
                }
            }
            if (pending_.fetch_sub(1) == 1) wake();
        }
    }

    /// Waits until ready(): checks it (pausing, then yielding the core) for kTeamSpin, then sleeps
    /// until a wake() finds it true.
    template <class Ready>
    void await(const Ready& ready) {
        Clock::time_point until{};
        for (int k = 0; !ready(); ++k) {
            if (k < 64) {
                relax();
                continue;
            }
            if (k == 64) until = Clock::now() + kTeamSpin;
            if (Clock::now() < until) {
                std::this_thread::yield();  // on a busy core: lets a thread with work run
                continue;
            }
            std::unique_lock<std::mutex> lock(mutex_);
            sleepers_.fetch_add(1);  // before the check under the lock: a wake() after this sees it
            cv_.wait(lock, ready);
            sleepers_.fetch_sub(1);
            return;
        }
    }

    /// Wakes the sleepers after a change of generation_ or pending_ (sequentially consistent: either
    /// the sleeper's check sees the change or this sees the sleeper).
    void wake() {
        if (sleepers_.load() == 0) return;
        std::lock_guard<std::mutex> lock(mutex_);
        cv_.notify_all();
    }

    /// Keeps the first exception of the current job.
    void keep() {
        std::lock_guard<std::mutex> lock(mutex_);
        if (!error_) error_ = std::current_exception();
    }

    std::vector<std::thread> threads_;   // helper t is threads_[t − 1]
    std::atomic<unsigned> generation_{0};  // raised once per job (and to stop)
    std::atomic<int> pending_{0};          // helpers that have not reported the current job
    std::atomic<int> sleepers_{0};         // threads asleep on cv_ (or about to be)
    std::atomic<bool> stop_{false};        // helpers end at the next generation
    const Share* job_ = nullptr;           // the current job (written before generation_ is raised)
    int n_ = 1;                            // its team size
    std::exception_ptr error_;             // its first exception (under mutex_)
    std::mutex mutex_;
    std::condition_variable cv_;
};

thread_local int teamCap = INT_MAX;  // the innermost TeamCap of this thread
std::atomic<int> defaultOverride{0};  // setDefaultThreads()
std::atomic<TeamClock> unitClock{nullptr};  // setTeamClock()

/// Now, on the clock that times units and probes (setTeamClock()).
Clock::time_point unitNow() {
    const TeamClock now = unitClock.load();
    return now ? now() : Clock::now();
}

/// The probe running on this thread (an AdaptiveTeam::Unit), as teamThreads() sees it: its loops use
/// `size` threads until `until`, then `fallback` (the current size); it counts them.
struct ProbeLimit {
    bool active = false;
    int size = 1, fallback = 1;
    Clock::time_point until{}, cutAt{};  // cutAt: when the first loop found `until` passed (else zero)
    long loops = 0, before = 0;          // loops the unit started, and those with `size` threads
};
thread_local ProbeLimit probeLimit;
}  // namespace

void runShares(int threads, const Share& share) {
    if (threads <= 1) return share(0, 1);
    thread_local Helpers helpers;  // this thread's helpers, joined when it ends
    helpers.run(threads, share);
}

int teamThreads(int threads) {
    int cap = teamCap;
    if (ProbeLimit& p = probeLimit; p.active) {
        ++p.loops;
        if (p.cutAt == Clock::time_point{}) {
            if (const auto now = unitNow(); now < p.until) ++p.before;
            else p.cutAt = now;
        }
        cap = std::min(cap, p.cutAt == Clock::time_point{} ? p.size : p.fallback);
    }
#ifdef CLOTHLAB_WEB
    cap = 1;  // the browser build has no threads, whatever solver.threads asks for
#endif
    return std::max(1, std::min(threads, cap));
}

void forEachShare(int count, int threads, int minParallel, const std::function<void(int begin, int end)>& each) {
    const int n = teamThreads(threads);
    if (n <= 1 || count < minParallel) return each(0, count);
    runShares(n, [&](int t, int n) { each(count * t / n, count * (t + 1) / n); });
}

TeamCap::TeamCap(int most) : outer_(teamCap) { teamCap = std::min(teamCap, most); }
TeamCap::~TeamCap() { teamCap = outer_; }

int defaultThreads() {
    const int set = defaultOverride.load();
#ifdef CLOTHLAB_WEB
    (void)set;
    return 1;  // the browser build (cmake/web.cmake) has no threads
#else
    return set > 0 ? set : std::max(1, omp_get_max_threads());
#endif
}

void setDefaultThreads(int threads) { defaultOverride.store(std::max(0, threads)); }

void setTeamClock(TeamClock now) { unitClock.store(now); }

AdaptiveTeam::AdaptiveTeam(int requested) {
    size_[1] = requested > 0 ? requested : defaultThreads();
    adaptive_ = requested <= 0 && size_[1] > 1;
}

void AdaptiveTeam::record(double seconds) {
    const int s = adaptive_ ? now_ ^ probing_ : size_[1] == 1 ? 0 : 1;  // the size that ran
    ++units_[s];
    if (!adaptive_) return;
    const bool probe = probing_ != 0;
    probing_ = 0;
    if (units_[s] > 1) {  // the first unit of a size is not counted
        const bool fresh = counted_[s]++ == 0 || probe;
        mean_[s] = fresh ? seconds : mean_[s] + (seconds - mean_[s]) / 4;
    }
    if (counted_[1] == 0) return;  // the start: most() threads until one unit counts,
    const int other = now_ ^ 1;
    if (counted_[0] == 0) {       // then one thread
        probing_ = 1;
        return;
    }
    const double keep = 1.0 - kMargin;  // the other size must be faster by the margin
    if (probe) {  // the other size just ran: keep the faster
        const bool won = mean_[other] < keep * mean_[now_];
        if (won && !confirmed_) {  // won once: one more unit of that size decides
            confirmed_ = true;
            probing_ = 1;
            return;
        }
        confirmed_ = false;
        if (won) {
            now_ = other;
            ++switches_;
            interval_ = kFirstInterval;
        } else {
            interval_ = std::min(2 * interval_, kLongestInterval);
        }
        untilProbe_ = interval_;
        return;
    }
    if (--untilProbe_ <= 0 || keep * mean_[now_] > mean_[other]) probing_ = 1;
}

AdaptiveTeam::Unit::Unit(AdaptiveTeam& team)
    : team_(team),
      probe_(team.adaptive_ && team.probing_ && team.counted_[team.now_] > 0 && !probeLimit.active),  // a probe with a time to beat
      cap_(probe_ ? team.most() : team.threads()),  // a probe's loops: probeLimit
      start_(unitNow()) {
    if (!probe_) return;
    const double beat = (1.0 - kMargin) * team.mean_[team.now_];  // the time a probe must beat, s
    probeLimit = {true, team.threads(), team.size_[team.now_],
                  start_ + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(beat)), {}, 0, 0};
}

AdaptiveTeam::Unit::~Unit() {
    const auto end = unitNow();
    double seconds = std::chrono::duration<double>(end - start_).count();
    if (probe_) {
        const ProbeLimit p = std::exchange(probeLimit, ProbeLimit{});
        // Cut short: the probe's whole unit, estimated from the share of loops it ran by then.
        if (p.cutAt != Clock::time_point{} && p.before > 0)
            seconds = std::chrono::duration<double>(p.cutAt - start_).count() * static_cast<double>(p.loops) / static_cast<double>(p.before);
    }
    team_.record(seconds);
}

}  // namespace clothlab
