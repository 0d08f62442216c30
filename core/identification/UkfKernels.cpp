#include "core/identification/UkfKernels.h"

#include <cmath>

namespace hsmu::ukfkernels {

bool choleskyInPlace(Eigen::MatrixXd& a) {
    const Eigen::Index n = a.rows();
    double* m = a.data();
    for (Eigen::Index j = 0; j < n; ++j) {
        double* cj = m + j * n;
        double d = cj[j];
        for (Eigen::Index k = 0; k < j; ++k) {
            d -= m[j + k * n] * m[j + k * n];
        }
        if (!(d > 0.0) || !std::isfinite(d)) {
            return false;
        }
        d = std::sqrt(d);
        cj[j] = d;
        for (Eigen::Index k = 0; k < j; ++k) {
            const double* ck = m + k * n;
            const double ljk = ck[j];
            for (Eigen::Index i = j + 1; i < n; ++i) {
                cj[i] -= ck[i] * ljk;
            }
        }
        const double inv = 1.0 / d;
        for (Eigen::Index i = j + 1; i < n; ++i) {
            cj[i] *= inv;
        }
        for (Eigen::Index i = 0; i < j; ++i) {
            cj[i] = 0.0;
        }
    }
    return true;
}

void symmetrize(Eigen::MatrixXd& m) {
    for (Eigen::Index j = 0; j < m.cols(); ++j) {
        for (Eigen::Index i = j + 1; i < m.rows(); ++i) {
            const double v = 0.5 * (m(i, j) + m(j, i));
            m(i, j) = v;
            m(j, i) = v;
        }
    }
}

void weightedOuter(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b, const Eigen::VectorXd& w,
                   Eigen::MatrixXd& out) {
    const Eigen::Index m = a.rows(), n = b.rows(), k = a.cols();
    out.setZero(m, n);
    double* __restrict o = out.data();
    for (Eigen::Index c = 0; c < k; ++c) {
        const double wc = w(c);
        if (wc == 0.0) {
            continue;
        }
        const double* __restrict ac = a.data() + c * m;
        const double* __restrict bc = b.data() + c * n;
        for (Eigen::Index j = 0; j < n; ++j) {
            const double s = wc * bc[j];
            for (Eigen::Index i = 0; i < m; ++i) {
                o[i + j * m] += ac[i] * s;
            }
        }
    }
}

void weightedGram(const Eigen::MatrixXd& a, const Eigen::VectorXd& w, Eigen::MatrixXd& out) {
    const Eigen::Index m = a.rows(), k = a.cols();
    out.setZero(m, m);
    double* __restrict o = out.data();
    for (Eigen::Index c = 0; c < k; ++c) {
        const double wc = w(c);
        if (wc == 0.0) {
            continue;
        }
        const double* __restrict ac = a.data() + c * m;
        for (Eigen::Index j = 0; j < m; ++j) {
            const double s = wc * ac[j];
            for (Eigen::Index i = j; i < m; ++i) {
                o[i + j * m] += ac[i] * s;
            }
        }
    }
    for (Eigen::Index j = 0; j < m; ++j) {
        for (Eigen::Index i = j + 1; i < m; ++i) {
            o[j + i * m] = o[i + j * m];
        }
    }
}

void solveRightInPlace(const Eigen::MatrixXd& lower, Eigen::MatrixXd& b) {
    // K L L^T = B: first Y L^T = B (column by column, forward), then K L = Y (backward).
    const Eigen::Index m = lower.rows(), r = b.rows();
    for (Eigen::Index j = 0; j < m; ++j) {
        for (Eigen::Index k = 0; k < j; ++k) {
            const double l = lower(j, k);
            for (Eigen::Index i = 0; i < r; ++i) {
                b(i, j) -= b(i, k) * l;
            }
        }
        const double inv = 1.0 / lower(j, j);
        for (Eigen::Index i = 0; i < r; ++i) {
            b(i, j) *= inv;
        }
    }
    for (Eigen::Index j = m - 1; j >= 0; --j) {
        for (Eigen::Index k = j + 1; k < m; ++k) {
            const double l = lower(k, j);
            for (Eigen::Index i = 0; i < r; ++i) {
                b(i, j) -= b(i, k) * l;
            }
        }
        const double inv = 1.0 / lower(j, j);
        for (Eigen::Index i = 0; i < r; ++i) {
            b(i, j) *= inv;
        }
    }
}

} // namespace hsmu::ukfkernels
