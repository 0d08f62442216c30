#pragma once
// Partition: a linear reference structure M x'' + C x' + K x = -M iota ag split into a
// numerical substructure and a linear experimental one at one DOF (docs/rths.md, "The
// partition"): Mn = M - Me, Cn = C - Ce, Kn = K - Ke with Me = me e_j e_j^T (and Ce, Ke alike).
// The numerical substructure then obeys
//     Mn x'' + Cn x' + Kn x = -M iota ag - e_j fe                                  (rths.md S1)
// with fe the experimental substructure's measured force. SI units: kg, N/m, N s/m, m, s.
//
// The RTHS benchmark's reference structures (Silva et al. 2020, cases 1-4) and the partition's
// critical delay: the smallest pure delay tau on fe for which the coupled loop
//     1 + Gn_jj(s) Ge(s) e^{-s tau} = 0,   Gn = (Mn s^2 + Cn s + Kn)^-1,  Ge = me s^2 + ce s + ke
// has a root on the imaginary axis (S2), found from the gain crossovers |Gn_jj Ge| = 1.

#include <Eigen/Core>

#include <string>

namespace hsmu::rths {

struct LinearStructure {
    Eigen::MatrixXd m, c, k; ///< [kg], [N s/m], [N/m]
    Eigen::VectorXd iota;    ///< influence vector of the ground acceleration [-]
};

struct Specimen {
    int dof = 0;      ///< the DOF the experimental substructure sits at (0-based)
    double me = 0.0;  ///< [kg]
    double ce = 0.0;  ///< [N s/m]
    double ke = 0.0;  ///< [N/m]
};

struct Partition {
    LinearStructure reference;
    LinearStructure numerical; ///< Mn, Cn, Kn; iota as the reference's (its load is -M iota ag)
    Specimen specimen;
};

Partition partition(const LinearStructure& reference, const Specimen& specimen);

/// Classical damping with the same ratio zeta in every mode: C = Phi^-T diag(2 zeta w_i M_i)
/// Phi^-1, w_i rounded to roundTo [rad/s] first when roundTo > 0 (the benchmark rounds to 0.01).
Eigen::MatrixXd modalDamping(const Eigen::MatrixXd& m, const Eigen::MatrixXd& k, double zeta,
                             double roundTo = 0.0);
/// Natural frequencies [Hz], ascending.
Eigen::VectorXd naturalFrequencies(const Eigen::MatrixXd& m, const Eigen::MatrixXd& k);

/// The RTHS benchmark's reference structure for case 1..4 (throws std::invalid_argument else).
LinearStructure benchmarkReference(int benchmarkCase);

/// Critical delay of the partition [s] (eq. S2); infinity when |L| never reaches 1.
double criticalDelay(const Partition& p);

} // namespace hsmu::rths
