// BoucWen::integrateStates(): the backward-Euler step of many problems with one increment (the
// UKF's sigma points), four problems per vector (GCC vector extensions). Every lane performs
// exactly the scalar operations of BackwardEuler::iterate() (BoucWenNewton.h) in the same
// order, each correctly rounded (no contraction into fused multiply-adds: this file is built
// with -ffp-contract=off); only the decisions (convergence, failure) are taken lane by lane.
// |z|^n: BatchMath::Exact calls absPow() (BoucWenNewton.h) lane by lane, so the end states are
// those of integrateState() bit for bit; BatchMath::Fast calls glibc's AVX2 vector pow (libmvec)
// once per vector on processors with AVX2, from a function compiled for AVX2 (selected at run time;
// the rest of the program stays baseline x86-64). Fast halves the step of the 19 sigma points
// (docs/benchmarks.md): pow was a third of it, and the vectors also divide four lanes at a time.

#include "core/hysteresis/BoucWen.h"

#include "core/hysteresis/BoucWenNewton.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>

namespace hsmu {

namespace {

using namespace boucwen;

constexpr int kLanes = 4;
using Vec = double __attribute__((vector_size(kLanes * sizeof(double))));
using Mask = std::int64_t __attribute__((vector_size(kLanes * sizeof(double))));

// Vectors per block: a block's vectors advance one Newton iteration per round (roundWith()),
// so that the processor overlaps their independent chains. 8 vectors hold the 19 sigma points
// of L = 9.
constexpr int kVectorsPerBlock = 8;
constexpr std::size_t kBlock = kLanes * kVectorsPerBlock;

// Vector helpers are always inlined: into the AVX2 function they become AVX2 code, and no
// vector is ever passed between functions of different instruction sets.

// std::abs: the sign bit cleared (-0 becomes +0, as std::abs does).
[[gnu::always_inline]] inline Vec absOf(const Vec& value) {
    Vec v = value;
    const Mask magnitude = ~(Mask{} + INT64_MIN);
    Mask bits;
    std::memcpy(&bits, &v, sizeof v);
    bits &= magnitude;
    std::memcpy(&v, &bits, sizeof v);
    return v;
}

// signOf() per lane: (v > 0) - (v < 0) as a double (comparisons give -1 for true).
[[gnu::always_inline]] inline Vec signOfLanes(const Vec& v) {
    return __builtin_convertvector((v < 0.0) - (v > 0.0), Vec);
}

// The problems of one vector in struct-of-arrays form (lanes without a problem hold benign
// values and are never read back).
struct Lanes {
    // Left uninitialized until idle() or load(): a block's vectors are set up every call.
    Vec c, z0, e0, z, a0, deltaA, deltaNu, deltaEta, beta, gamma, n;
    std::array<std::size_t, kLanes> problem; ///< index into the batch
    unsigned running;                        ///< bit l: lane l is iterating
    int iterations;

    // Every lane holds the (admissible) default parameters in the virgin state.
    void idle() {
        const BoucWenParameters defaults;
        for (int lane = 0; lane < kLanes; ++lane) {
            fill(lane, defaults, BoucWenState{});
        }
        running = 0;
        iterations = 0;
    }

    void load(int lane, std::size_t i, const BoucWenParameters& p, const BoucWenState& from) {
        fill(lane, p, from);
        problem[static_cast<std::size_t>(lane)] = i;
        running |= 1u << lane;
    }

    void fill(int lane, const BoucWenParameters& p, const BoucWenState& from) {
        // As BackwardEuler's constructor: c = (1 - alpha) k0.
        c[lane] = (1.0 - p.alpha) * p.k0;
        z0[lane] = from.z;
        e0[lane] = from.e;
        z[lane] = from.z;
        a0[lane] = p.A0;
        deltaA[lane] = p.deltaA;
        deltaNu[lane] = p.deltaNu;
        deltaEta[lane] = p.deltaEta;
        beta[lane] = p.beta;
        gamma[lane] = p.gamma;
        n[lane] = p.n;
    }
};

struct Batch {
    std::span<const BoucWenParameters> p;
    std::span<const BoucWenState> from;
    double dx;
    std::span<BoucWenIncrement> out;
};

// The rest of one Newton iteration of every running lane (BackwardEuler::iterate(), same
// operations in the same order) given absZn = |z|^n, then each lane's decision.
[[gnu::always_inline]] inline void finishIteration(Lanes& v, const Vec& absZn, const Batch& b) {
    const double dx = b.dx;
    const Vec z = v.z, z0 = v.z0;
    const Vec dedz = v.c * dx;
    const Vec e = v.e0 + v.c * z * dx;
    const Vec da = v.a0 - v.deltaA * e; // Degradation: A, nu, eta (Eqs 4-6)
    const Vec nu = 1.0 + v.deltaNu * e;
    const Vec eta = 1.0 + v.deltaEta * e;
    const Vec absZ = absOf(z);
    const Vec psi = v.gamma + v.beta * signOfLanes(dx * z);
    const Vec phi = da - absZn * psi * nu;
    const Vec r = z - z0 - dx * phi / eta;
    const Vec dAbsZn = absZ > 0.0 ? v.n * absZn / absZ * signOfLanes(z) : Vec{};
    const Vec dPhi = -v.deltaA * dedz - dAbsZn * psi * nu - absZn * psi * v.deltaNu * dedz;
    const Vec dEta = v.deltaEta * dedz;
    const Vec dr = 1.0 - dx * (dPhi * eta - phi * dEta) / (eta * eta);
    const Vec delta = r / dr;
    const Vec next = z - delta;
    v.z = next;
    const bool last = ++v.iterations >= kMaxNewtonIterations;
    // Lanes that simply go on (finite and within the cheap bound, so within the bound, and not
    // converged) need no decision of their own; usually all of them do.
    const Vec absNext = absOf(next), absZ0 = absOf(z0);
    const Mask goesOn = (absNext <= kWildJumpFactor * absZ0) &
                        (absOf(delta) > kRelativeTolerance * (absNext < absZ0 ? absZ0 : absNext));
    unsigned goingOn = 0;
    for (int lane = 0; lane < kLanes; ++lane) {
        goingOn |= goesOn[lane] != 0 ? 1u << lane : 0u;
    }
    if (!last && (v.running & ~goingOn) == 0) {
        return;
    }
    for (int lane = 0; lane < kLanes; ++lane) {
        const auto l = static_cast<std::size_t>(lane);
        if ((v.running & (1u << lane)) == 0) {
            continue;
        }
        const std::size_t i = v.problem[l];
        const double zNext = next[lane];
        bool done = false, failed = false;
        // StepLimits::withinZBound() with its cheap test first (the same decision; the rare
        // lane beyond it gets the exact bound from a StepLimits of its own).
        const double absNext = std::abs(zNext);
        if (!std::isfinite(zNext) || !(absNext <= kWildJumpFactor * std::abs(z0[lane]) ||
                                       StepLimits(b.p[i], b.from[i]).withinZBound(absNext))) {
            failed = true;
        } else if (std::abs(delta[lane]) <=
                   kRelativeTolerance * std::max(std::abs(zNext), std::abs(z0[lane]))) {
            const double eEnd = v.e0[lane] + v.c[lane] * zNext * dx;
            done = std::isfinite(eEnd);
            failed = !done;
            if (done) {
                b.out[i] = {LawStatus::Ok, {zNext, eEnd}, 0.0, 1};
            }
        } else {
            failed = last;
        }
        if (failed) {
            // Not a single plain step: integrateState() repeats the same iterations, then
            // halves the increment or reports the failure.
            b.out[i] = BoucWen::integrateState(b.p[i], b.from[i], dx);
        }
        if (done || failed) {
            v.running &= ~(1u << lane);
        }
    }
}

// One Newton iteration of every running vector of a block: first the powers of all of them
// (independent calls the processor can overlap), then the rest. Inlined into one function per
// instruction set (roundExact(), roundAvx2()).
template <class Pow>
[[gnu::always_inline]] inline void roundWith(Lanes* vectors, int count, const Batch& b, Pow pow) {
    std::array<Vec, kVectorsPerBlock> absZn;
    for (int k = 0; k < count; ++k) {
        if (vectors[k].running != 0) {
            absZn[static_cast<std::size_t>(k)] = pow(vectors[k], absOf(vectors[k].z));
        }
    }
    for (int k = 0; k < count; ++k) {
        if (vectors[k].running != 0) {
            finishIteration(vectors[k], absZn[static_cast<std::size_t>(k)], b);
        }
    }
}

// absPow() lane by lane (running lanes only): the results of integrateState(), bit for bit.
void roundExact(Lanes* vectors, int count, const Batch& b) {
    roundWith(
        vectors, count, b, [](const Lanes& lanes, const Vec& absZ) __attribute__((always_inline)) {
            Vec out{};
            for (int lane = 0; lane < kLanes; ++lane) {
                if ((lanes.running & (1u << lane)) != 0) {
                    out[lane] = absPow(absZ[lane], lanes.n[lane]);
                }
            }
            return out;
        });
}

#if defined(HSMU_HAVE_LIBMVEC_AVX2)
// glibc's vector pow (libmvec, the x86-64 vector function ABI, AVX2 variant): four lanes per
// call, within 1 ulp of std::pow.
#pragma GCC push_options
#pragma GCC target("avx2")
extern "C" Vec _ZGVdN4vv_pow(Vec x, Vec y);

void roundAvx2(Lanes* vectors, int count, const Batch& b) {
    // (Not always_inline: roundWith() is compiled for the baseline until it is inlined here.)
    roundWith(vectors, count, b,
              [](const Lanes& lanes, const Vec& absZ) { return _ZGVdN4vv_pow(absZ, lanes.n); });
}
#pragma GCC pop_options

bool vectorPowAvailable() {
    static const bool available = __builtin_cpu_supports("avx2");
    return available;
}
#else
void roundAvx2(Lanes* vectors, int count, const Batch& b) {
    roundExact(vectors, count, b);
}

bool vectorPowAvailable() {
    return false;
}
#endif

} // namespace

void BoucWen::integrateStates(std::span<const BoucWenParameters> p,
                              std::span<const BoucWenState> from, double dx,
                              std::span<BoucWenIncrement> out, BatchMath math) {
    const bool vector = math == BatchMath::Fast && vectorPowAvailable();
    // A problem that is not a plain single step from the start (inadmissible, non-finite, an
    // increment to halve, as too long or too stiff an unloading) is left to integrateState(), which
    // takes the same decisions.
    const std::size_t count = std::min({p.size(), from.size(), out.size()});
    for (std::size_t first = 0; first < count; first += kBlock) {
        std::array<Lanes, kVectorsPerBlock> vectors;
        Batch batch{p, from, dx, out};
        const std::size_t size = std::min(kBlock, count - first);
        int used = 0, lane = 0;
        for (std::size_t k = 0; k < size; ++k) {
            const std::size_t i = first + k;
            if (admissibleParameters(p[i]) && std::isfinite(dx) && std::isfinite(from[i].z) &&
                std::isfinite(from[i].e) && StepLimits(p[i], from[i]).withinMaxStep(std::abs(dx)) &&
                withinUnloadingStep(p[i], from[i], dx)) {
                if (lane == 0) {
                    vectors[static_cast<std::size_t>(used)].idle();
                }
                vectors[static_cast<std::size_t>(used)].load(lane, i, p[i], from[i]);
                if (++lane == kLanes) {
                    lane = 0;
                    ++used;
                }
            } else {
                out[i] = integrateState(p[i], from[i], dx);
            }
        }
        const int vectorCount = used + (lane > 0 ? 1 : 0);
        const auto running = [&] {
            return std::any_of(vectors.begin(), vectors.begin() + vectorCount,
                               [](const Lanes& v) { return v.running != 0; });
        };
        while (running()) {
            if (vector) {
                roundAvx2(vectors.data(), vectorCount, batch);
            } else {
                roundExact(vectors.data(), vectorCount, batch);
            }
        }
    }
}

bool BoucWen::fastBatchMathAvailable() {
    return vectorPowAvailable();
}

const char* BoucWen::fastBatchMathName() {
    return vectorPowAvailable() ? "libmvec AVX2 vector pow" : "std::pow";
}

} // namespace hsmu
