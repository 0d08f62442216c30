#include "core/identification/UkfKernels.h"

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <type_traits>

namespace hsmu::ukfkernels {

// Each public kernel is also compiled for AVX2 and chosen at load time where the processor has
// it (GCC function multiversioning), with everything it calls inlined into it (flatten: else
// the clone would call the baseline loops): its plain loops then work on four doubles at a
// time. The results are the same bit for bit: AVX2 brings no fused multiply-add, and
// vectorizing element-wise loops (not reductions, which stay in order) changes no rounding.
// Not under ThreadSanitizer: the loader runs the clones' resolver before TSan's runtime is up,
// and the instrumented resolver crashes every program at start (scripts/test-tsan.sh).
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && !defined(__SANITIZE_THREAD__)
#define HSMU_KERNEL_CLONES __attribute__((target_clones("avx2", "default"), flatten))
#else
#define HSMU_KERNEL_CLONES
#endif

namespace {

using Index = Eigen::Index;

// The kernels are compiled for any size and also for the sizes of the Bouc-Wen estimator, its
// state (kBoucWenUkfSize) and its scalar measurement (through dispatch(), or as the
// fixed-size choleskyFixed() and gramFixed()). With the bounds known the compiler unrolls and
// vectorizes the short loops, whose set-up otherwise costs more than their work at this size.
// The floating-point operations and their order are the same for every size, and so are the
// results, bit for bit.
constexpr Index kStateSize = 9;

// Calls kernel with std::integral_constant N = n for the sizes above, else N = 0 (any size).
template <class Kernel> decltype(auto) dispatch(Index n, Kernel&& kernel) {
    switch (n) {
    case 1:
        return kernel(std::integral_constant<Index, 1>{});
    case kStateSize:
        return kernel(std::integral_constant<Index, kStateSize>{});
    default:
        return kernel(std::integral_constant<Index, 0>{});
    }
}

template <Index N> Index sizeOr(Index dynamic) {
    return N > 0 ? N : dynamic;
}

bool cholesky(double* m, Index n) {
    for (Index j = 0; j < n; ++j) {
        double* cj = m + j * n;
        double d = cj[j];
        for (Index k = 0; k < j; ++k) {
            d -= m[j + k * n] * m[j + k * n];
        }
        if (!(d > 0.0) || !std::isfinite(d)) {
            return false;
        }
        d = std::sqrt(d);
        cj[j] = d;
        for (Index k = 0; k < j; ++k) {
            const double* ck = m + k * n;
            const double ljk = ck[j];
            for (Index i = j + 1; i < n; ++i) {
                cj[i] -= ck[i] * ljk;
            }
        }
        const double inv = 1.0 / d;
        for (Index i = j + 1; i < n; ++i) {
            cj[i] *= inv;
        }
        for (Index i = 0; i < j; ++i) {
            cj[i] = 0.0;
        }
    }
    return true;
}

// cholesky() for a fixed size N (the dynamic loops of varying length do not unroll), column J (a
// template parameter, so that its rows J..N-1 are a fixed-size segment the compiler keeps in vector
// registers) then the next. The pivot is row J of the updated segment, a_JJ - sum_k l_Jk^2 in the
// same order as in cholesky().
template <Index N, Index J = 0> bool choleskyFixed(double* m) {
    if constexpr (J == N) {
        return true;
    } else {
        using Segment = Eigen::Matrix<double, N - J, 1>;
        double* column = m + J * N;
        Segment lower = Eigen::Map<const Segment>(column + J);
        for (Index k = 0; k < J; ++k) {
            const double* ck = m + k * N;
            lower -= Eigen::Map<const Segment>(ck + J) * ck[J];
        }
        const double pivot = lower(0);
        if (!(pivot > 0.0) || !std::isfinite(pivot)) {
            return false;
        }
        const double d = std::sqrt(pivot);
        const double inv = 1.0 / d;
        for (Index i = 0; i < J; ++i) {
            column[i] = 0.0;
        }
        column[J] = d;
        for (Index i = 1; i < N - J; ++i) {
            column[J + i] = lower(i) * inv;
        }
        return choleskyFixed<N, J + 1>(m);
    }
}

template <Index N> void symmetric(double* m, Index dynamicN) {
    const Index n = sizeOr<N>(dynamicN);
    for (Index j = 0; j < n; ++j) {
        for (Index i = j + 1; i < n; ++i) {
            const double v = 0.5 * (m[i + j * n] + m[j + i * n]);
            m[i + j * n] = v;
            m[j + i * n] = v;
        }
    }
}

// o (m x n, zeroed) += sum_c w_c a_c b_c^T.
template <Index M>
void outer(const double* __restrict a, const double* __restrict b, const double* __restrict w,
           double* __restrict o, Index dynamicM, Index n, Index k) {
    const Index m = sizeOr<M>(dynamicM);
    for (Index c = 0; c < k; ++c) {
        const double wc = w[c];
        if (wc == 0.0) {
            continue;
        }
        const double* __restrict ac = a + c * m;
        const double* __restrict bc = b + c * n;
        for (Index j = 0; j < n; ++j) {
            const double s = wc * bc[j];
            for (Index i = 0; i < m; ++i) {
                o[i + j * m] += ac[i] * s;
            }
        }
    }
}

// o (m x m, zeroed) += sum_c w_c a_c a_c^T on the lower triangle, then mirrored.
void gram(const double* __restrict a, const double* __restrict w, double* __restrict o, Index m,
          Index k) {
    for (Index c = 0; c < k; ++c) {
        const double wc = w[c];
        if (wc == 0.0) {
            continue;
        }
        const double* __restrict ac = a + c * m;
        for (Index j = 0; j < m; ++j) {
            const double s = wc * ac[j];
            for (Index i = j; i < m; ++i) {
                o[i + j * m] += ac[i] * s;
            }
        }
    }
    for (Index j = 0; j < m; ++j) {
        for (Index i = j + 1; i < m; ++i) {
            o[j + i * m] = o[i + j * m];
        }
    }
}

// gram() for a fixed size M, column J (a template parameter: its rows J..M-1 are a fixed-size
// accumulator the compiler keeps in vector registers) then the next; each element summed over
// c in the same order as in gram().
template <Index M, Index J = 0>
void gramFixed(const double* __restrict a, const double* __restrict w, double* __restrict o,
               Index k) {
    if constexpr (J < M) {
        using Segment = Eigen::Matrix<double, M - J, 1>;
        Segment sum = Segment::Zero();
        for (Index c = 0; c < k; ++c) {
            const double wc = w[c];
            if (wc == 0.0) {
                continue;
            }
            const double* ac = a + c * M;
            sum += Eigen::Map<const Segment>(ac + J) * (wc * ac[J]);
        }
        for (Index i = 0; i < M - J; ++i) {
            o[J + i + J * M] = sum(i);
            o[J + (J + i) * M] = sum(i);
        }
        gramFixed<M, J + 1>(a, w, o, k);
    }
}

// dev_c = points_c+1 - points_0, c < k (m rows).
template <Index M>
void deviate(const double* __restrict points, double* __restrict dev, Index dynamicM, Index k) {
    const Index m = sizeOr<M>(dynamicM);
    for (Index c = 0; c < k; ++c) {
        for (Index r = 0; r < m; ++r) {
            dev[r + c * m] = points[r + (1 + c) * m] - points[r];
        }
    }
}

template <Index M>
void moments(const double* __restrict points, const double* __restrict w, double noise,
             double* __restrict dev, double* __restrict mu, Index dynamicM, Index pairs) {
    const Index m = sizeOr<M>(dynamicM);
    const double* __restrict centre = points;
    deviate<M>(points, dev, m, 2 * pairs);
    for (Index r = 0; r < m; ++r) {
        mu[r] = 0.0;
    }
    for (Index j = 0; j < pairs; ++j) {
        const double wj = w[j];
        if (wj == 0.0) {
            continue;
        }
        const double* __restrict plus = points + (1 + j) * m;
        const double* __restrict minus = points + (1 + pairs + j) * m;
        for (Index r = 0; r < m; ++r) {
            const double second = dev[r + j * m] + dev[r + (pairs + j) * m];
            const double floor =
                noise * (std::abs(plus[r]) + std::abs(minus[r]) + 2.0 * std::abs(centre[r]));
            // Adding +0 instead (branch-free) leaves mu[r] unchanged: it starts at +0 and a sum
            // is never -0 then.
            mu[r] += std::abs(second) > floor ? wj * second : 0.0;
        }
    }
}

// out_j = x + scale root_j, j < n (n x n).
template <Index N>
void offset(const double* __restrict x, const double* __restrict root, double scale,
            double* __restrict out, Index dynamicN) {
    const Index n = sizeOr<N>(dynamicN);
    for (Index k = 0; k < n * n; k += n) {
        for (Index i = 0; i < n; ++i) {
            out[k + i] = scale * root[k + i] + x[i];
        }
    }
}

// Two doubles in one SSE2 register (GCC vector extensions): element-wise operations with the
// same rounding as the scalar ones.
using Pair = double __attribute__((vector_size(2 * sizeof(double))));
using PairMask = std::int64_t __attribute__((vector_size(2 * sizeof(double))));

Pair loadPair(const double* p) {
    Pair v;
    std::memcpy(&v, p, sizeof v);
    return v;
}

// offset(), and whether std::clamp into [lower, upper] would move any of the values written: it
// moves v exactly when v < lower or upper < v (never a NaN). For a fixed size, two rows at a
// time in vector registers.
template <Index N>
bool offsetOutside(const double* __restrict x, const double* __restrict root, double scale,
                   double* __restrict out, const double* __restrict lower,
                   const double* __restrict upper, Index dynamicN) {
    if constexpr (N == 0) {
        offset<0>(x, root, scale, out, dynamicN);
        std::int64_t moved = 0;
        for (Index k = 0; k < dynamicN * dynamicN; ++k) {
            const Index i = k % dynamicN;
            moved |= static_cast<std::int64_t>(out[k] < lower[i]) |
                     static_cast<std::int64_t>(upper[i] < out[k]);
        }
        return moved != 0;
    } else {
        constexpr Index pairs = N / 2;
        std::array<Pair, pairs> centre, low, high;
        for (Index p = 0; p < pairs; ++p) {
            centre[p] = loadPair(x + 2 * p);
            low[p] = loadPair(lower + 2 * p);
            high[p] = loadPair(upper + 2 * p);
        }
        PairMask moved{};
        bool movedLast = false;
        for (Index k = 0; k < N * N; k += N) {
            for (Index p = 0; p < pairs; ++p) {
                const Pair v = scale * loadPair(root + k + 2 * p) + centre[p];
                std::memcpy(out + k + 2 * p, &v, sizeof v);
                moved |= (v < low[p]) | (high[p] < v);
            }
            if constexpr (N % 2 == 1) {
                const double v = scale * root[k + N - 1] + x[N - 1];
                out[k + N - 1] = v;
                movedLast |= (v < lower[N - 1]) | (upper[N - 1] < v);
            }
        }
        return (moved[0] | moved[1]) != 0 || movedLast;
    }
}

template <Index N>
void mirror(const double* __restrict x, const double* __restrict plus, double* __restrict minus,
            Index dynamicN) {
    const Index n = sizeOr<N>(dynamicN);
    for (Index k = 0; k < n * n; k += n) {
        for (Index i = 0; i < n; ++i) {
            minus[k + i] = -(plus[k + i] - x[i]) + x[i];
        }
    }
}

} // namespace

HSMU_KERNEL_CLONES bool allFinite(const double* data, Index count) {
    // A double is finite unless its exponent bits are all ones, the one case in which adding
    // one to the exponent field carries into the sign bit. Integer operations and no early
    // exit: the loop vectorizes (Eigen's allFinite() tests value by value).
    constexpr std::uint64_t exponent = 0x7ff0000000000000, unit = 0x0010000000000000;
    std::uint64_t carry = 0;
    for (Index k = 0; k < count; ++k) {
        carry |= (std::bit_cast<std::uint64_t>(data[k]) & exponent) + unit;
    }
    return (carry >> 63) == 0;
}

HSMU_KERNEL_CLONES void offsetColumns(const Eigen::VectorXd& x, const Eigen::MatrixXd& root,
                                      double scale, double* out) {
    dispatch(x.size(), [&](auto n) { offset<n()>(x.data(), root.data(), scale, out, x.size()); });
}

HSMU_KERNEL_CLONES bool offsetColumnsOutside(const Eigen::VectorXd& x, const Eigen::MatrixXd& root,
                                             double scale, double* out,
                                             const Eigen::VectorXd& lower,
                                             const Eigen::VectorXd& upper) {
    return dispatch(x.size(), [&](auto n) {
        return offsetOutside<n()>(x.data(), root.data(), scale, out, lower.data(), upper.data(),
                                  x.size());
    });
}

HSMU_KERNEL_CLONES void mirrorColumns(const Eigen::VectorXd& x, const double* plus, double* minus) {
    dispatch(x.size(), [&](auto n) { mirror<n()>(x.data(), plus, minus, x.size()); });
}

HSMU_KERNEL_CLONES void deviations(const Eigen::MatrixXd& points, Eigen::MatrixXd& dev) {
    const Index m = points.rows(), k = points.cols() - 1;
    dev.resize(m, k);
    dispatch(m, [&](auto size) { deviate<size()>(points.data(), dev.data(), m, k); });
}

HSMU_KERNEL_CLONES bool choleskyInPlace(Eigen::MatrixXd& a) {
    switch (a.rows()) {
    case 1:
        return choleskyFixed<1>(a.data());
    case kStateSize:
        return choleskyFixed<kStateSize>(a.data());
    default:
        return cholesky(a.data(), a.rows());
    }
}

void symmetrize(Eigen::MatrixXd& m) {
    dispatch(m.rows(), [&](auto n) { symmetric<n()>(m.data(), m.rows()); });
}

HSMU_KERNEL_CLONES void weightedOuter(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b,
                                      const Eigen::VectorXd& w, Eigen::MatrixXd& out) {
    out.setZero(a.rows(), b.rows());
    dispatch(a.rows(), [&](auto m) {
        outer<m()>(a.data(), b.data(), w.data(), out.data(), a.rows(), b.rows(), a.cols());
    });
}

HSMU_KERNEL_CLONES void weightedGram(const Eigen::MatrixXd& a, const Eigen::VectorXd& w,
                                     Eigen::MatrixXd& out) {
    out.setZero(a.rows(), a.rows());
    switch (a.rows()) {
    case 1:
        return gramFixed<1>(a.data(), w.data(), out.data(), a.cols());
    case kStateSize:
        return gramFixed<kStateSize>(a.data(), w.data(), out.data(), a.cols());
    default:
        return gram(a.data(), w.data(), out.data(), a.rows(), a.cols());
    }
}

HSMU_KERNEL_CLONES void pairMoments(const Eigen::MatrixXd& points, const Eigen::VectorXd& w,
                                    double noise, Eigen::MatrixXd& dev, Eigen::VectorXd& mu) {
    const Index m = points.rows(), pairs = points.cols() / 2;
    dev.resize(m, 2 * pairs);
    mu.resize(m);
    dispatch(m, [&](auto size) {
        moments<size()>(points.data(), w.data(), noise, dev.data(), mu.data(), m, pairs);
    });
}

void addScaledOuter(Eigen::MatrixXd& m, double c, const Eigen::VectorXd& mu) {
    const Index n = mu.size();
    for (Index j = 0; j < n; ++j) {
        for (Index i = 0; i < n; ++i) {
            m(i, j) += (c * mu(i)) * mu(j);
        }
    }
}

void solveRightInPlace(const Eigen::MatrixXd& lower, Eigen::MatrixXd& b) {
    // K L L^T = B: first Y L^T = B (column by column, forward), then K L = Y (backward).
    const Index m = lower.rows(), r = b.rows();
    for (Index j = 0; j < m; ++j) {
        for (Index k = 0; k < j; ++k) {
            const double l = lower(j, k);
            for (Index i = 0; i < r; ++i) {
                b(i, j) -= b(i, k) * l;
            }
        }
        const double inv = 1.0 / lower(j, j);
        for (Index i = 0; i < r; ++i) {
            b(i, j) *= inv;
        }
    }
    for (Index j = m - 1; j >= 0; --j) {
        for (Index k = j + 1; k < m; ++k) {
            const double l = lower(k, j);
            for (Index i = 0; i < r; ++i) {
                b(i, j) -= b(i, k) * l;
            }
        }
        const double inv = 1.0 / lower(j, j);
        for (Index i = 0; i < r; ++i) {
            b(i, j) *= inv;
        }
    }
}

} // namespace hsmu::ukfkernels
