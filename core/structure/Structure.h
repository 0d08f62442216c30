#pragma once
// Structure: N-DOF lumped-mass model with elements, Rayleigh damping and equal-DOF
// constraints (docs/method.md, The paper's test frame: condition 1's rigid truss is the
// constraint u_slave = u_master, not a huge stiffness).
//
// Units: a consistent set; the presets use kN, m, s and t (tonne = kN s^2/m).
// Coordinates: "full" DOFs are the ones the user declares; constraints merge slaves into
// their masters, leaving the "free" DOFs the integrator works on: u_full = T u_free with T a
// 0/1 matrix (one 1 per row). All matrices returned here are over the free DOFs.
//
// Every matrix is sparse (Eigen::SparseMatrix, column-major): an element adds c c^T k0 over
// its DofTerms only, so K0 has O(elements) non-zeros and the cost of a step grows linearly
// with the model (docs/benchmarks.md, "Numerical substructures at scale"). T is applied as an
// index map (toFull, restoringForce); M = T^T M_full T is always diagonal (massDiagonal()).
// Frequencies: up to kDenseModalLimit free DOFs a dense generalized eigen-solve gives every
// mode; above it ModalAnalysis gives the lowest modes that damping needs (shift-invert
// Lanczos) and omega_max (Lanczos, capped by a Gershgorin bound), see ModalAnalysis.h.

#include "core/structure/Element.h"

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <memory>
#include <string>
#include <vector>

namespace hsmu {

struct RayleighDamping {
    double a0 = 0.0; ///< mass-proportional coefficient [1/s]
    double a1 = 0.0; ///< initial-stiffness-proportional coefficient [s]
    /// Coefficients giving damping ratio zeta at circular frequencies w1, w2 [rad/s]
    /// (zeta_i = a0 / (2 w_i) + a1 w_i / 2). With w1 == w2: a0 = zeta w, a1 = zeta / w.
    static RayleighDamping fromRatio(double zeta, double w1, double w2);
};

class Structure {
public:
    using SparseMatrix = Eigen::SparseMatrix<double>;
    /// Largest free DOF count whose frequencies come from a dense eigen-solve (all modes).
    static constexpr int kDenseModalLimit = 300;

    Structure() = default;
    Structure(const Structure&) = delete;
    Structure& operator=(const Structure&) = delete;

    /// Add a DOF with lumped mass [t] (a rotational DOF: [t m^2]) and its ground-motion
    /// influence iota (1: a horizontal translation the record shakes; 0: a rotation or a
    /// vertical DOF); returns its full index.
    int addDof(std::string name, double mass, double influence = 1.0);
    void addElement(std::unique_ptr<Element> element);
    /// Constrain u[slave] = u[master].
    void addEqualDof(int master, int slave);
    void setRayleigh(const RayleighDamping& d) { m_rayleigh = d; }
    /// Rayleigh damping with ratio zeta at modes i and j (1-based, of the initial-stiffness
    /// model); resolved in finalize(). A mode beyond the free DOF count is clamped.
    void setModalDamping(double zeta, int modeI, int modeJ);

    /// Validate and build T, M, K0, C and the frequencies. Throws std::invalid_argument with a clear sentence
    /// (bad DOF index, mass <= 0 on a free DOF, constraint cycle, no DOFs).
    void finalize();

    int fullDofCount() const { return static_cast<int>(m_dofNames.size()); }
    int freeDofCount() const { return static_cast<int>(m_t.cols()); }
    const std::vector<std::string>& dofNames() const { return m_dofNames; }
    const std::vector<std::unique_ptr<Element>>& elements() const { return m_elements; }
    Element* element(const std::string& name) const;

    const SparseMatrix& transform() const { return m_t; } ///< T, full x free
    const SparseMatrix& mass() const { return m_m; }      ///< M (free, diagonal) [t]
    const Eigen::VectorXd& massDiagonal() const { return m_mDiag; } ///< diag(M) [t]
    const SparseMatrix& initialStiffness() const { return m_k0; } ///< K0 (free) [kN/m]
    const SparseMatrix& damping() const { return m_c; }   ///< C (free) [kN s/m]
    /// True when C has no off-diagonal term (mass-proportional damping, or K0 diagonal):
    /// M + c C is then diagonal and an explicit step needs no solve.
    bool dampingIsDiagonal() const { return m_cDiagonal; }
    /// Free DOF index of each full DOF (u_full[i] = u_free[freeIndexOf()[i]]).
    const std::vector<int>& freeIndexOf() const { return m_freeOf; }
    const RayleighDamping& rayleigh() const { return m_rayleigh; }
    /// Effective earthquake load per unit ground acceleration: T^T M_full iota [t].
    const Eigen::VectorXd& influence() const { return m_influence; }
    /// Undamped circular frequencies [rad/s] of (K0, M), ascending: every mode up to
    /// kDenseModalLimit free DOFs, else the lowest max(modes of the damping, 3).
    const Eigen::VectorXd& frequencies() const { return m_omega; }
    /// Largest undamped circular frequency of (K0, M) [rad/s] (exact up to kDenseModalLimit
    /// free DOFs, else the Lanczos estimate from above of ModalAnalysis.h).
    double maxFrequency() const { return m_omegaMax; }
    /// Largest undamped circular frequency [rad/s] of (K0', M), K0' assembled from the
    /// elements' initial stiffness as they are now (after online updates changed a numerical
    /// element's law). K0, C and maxFrequency() stay those of finalize(): an update never
    /// changes them (docs/method.md, "The updated model"). Requires finalize().
    double updatedMaxFrequency() const;

    Eigen::VectorXd toFull(const Eigen::VectorXd& uFree) const;
    /// toFull into out, reusing its storage (no allocation once sized): once a step per
    /// vector of the published StepRecord (issue 27).
    void toFull(const Eigen::VectorXd& uFree, Eigen::VectorXd& out) const;

    /// Set every element's trial at free displacements u; experimental elements first (their
    /// targets go out before any numerical work). Returns the first failure.
    ElementStatus setTrial(const Eigen::VectorXd& uFree);
    /// Restoring force over the free DOFs at the current trial state.
    Eigen::VectorXd restoringForce() const;
    /// restoringForce() into r, reusing its storage (no allocation once sized; issue 27).
    void restoringForce(Eigen::VectorXd& r) const;
    /// Commit every element, specimens first; returns the first failure.
    ElementStatus commit();
    void revert();

private:
    void buildOrder();
    /// K0 over the free DOFs from the elements' current initial stiffness.
    SparseMatrix assembleInitialStiffness() const;

    std::vector<std::string> m_dofNames;
    std::vector<double> m_masses;
    std::vector<double> m_iota; // per full DOF
    std::vector<std::unique_ptr<Element>> m_elements;
    std::vector<std::pair<int, int>> m_equalDofs;
    RayleighDamping m_rayleigh;
    double m_modalZeta = -1.0;
    int m_modeI = 1, m_modeJ = 2;
    std::vector<Element*> m_order; // specimens first, then numerical elements (finalize())
    std::vector<int> m_freeOf;
    SparseMatrix m_t, m_m, m_k0, m_c;
    bool m_cDiagonal = true;
    Eigen::VectorXd m_mDiag, m_influence, m_omega;
    double m_omegaMax = 0.0;
    mutable Eigen::VectorXd m_rFull; // restoringForce() scratch
    Eigen::VectorXd m_trialFull;     // setTrial() scratch
};

} // namespace hsmu
