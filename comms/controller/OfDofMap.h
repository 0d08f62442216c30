#pragma once
// OfDofMap: how the control DOFs of an OpenFresco client (e.g. OpenSees' `element
// genericClient -node 1 2 -dof 1 -dof 1`: global DOFs, no basic transformation) map onto the
// specimens of hsmu-controller (docs/openfresco.md "Several DOFs"). A linear map B (specimens x
// DOFs), each DOF on at most one specimen:
//
//   specimen deformation    d = B u                       (u: the client's ctrl disp, n DOFs)
//   force on the DOFs       F = B^T f                     (f: the specimens' measured forces)
//   stiffness               K = B^T diag(k) B             (k: the specimens' tangents)
//   measured DOF disp       u_m = u + B^T (B B^T)^-1 (d_m - B u)   (d_m: measured deformation)
//
// so that B u_m = d_m (the least-norm correction; u_m = u when the specimen is where it was
// commanded). Configuration: `controller.serverDofs`, one entry per client DOF, in the client's
// order: {"specimen": NAME, "factor": 1} (factor default 1; a two-node link is [{"specimen":
// "S", "factor": -1}, {"specimen": "S"}]) or {} for a DOF no specimen sits on (its force is 0).
// Absent: one DOF per specimen in configuration order (B = I). No sockets here.

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace hsmu::comms {

class OfDofMap {
public:
    /// B = I for `specimens` specimens.
    explicit OfDofMap(int specimens = 0);
    /// From the configuration's `controller` section (may be null / lack serverDofs) and the
    /// specimens' names in configuration order. Throws ConfigError naming
    /// controller.serverDofs[i] and the field.
    static OfDofMap parse(const nlohmann::json& controller, const std::vector<std::string>& names,
                          const std::string& file);

    int dofs() const { return static_cast<int>(m_specimen.size()); }
    int specimens() const { return m_specimens; }
    bool configured() const { return m_configured; }
    /// "2 DOFs from controller.serverDofs onto 1 specimen" / "1 DOF per specimen (1 specimen)".
    std::string describe() const;

    std::vector<double> deformations(const std::vector<double>& u) const;
    std::vector<double> forces(const std::vector<double>& f) const;
    /// Column-major n x n.
    std::vector<double> stiffness(const std::vector<double>& k) const;
    std::vector<double> measuredDisp(const std::vector<double>& u, const std::vector<double>& dm,
                                     const std::vector<double>& dc) const;

private:
    int m_specimens = 0;
    bool m_configured = false;
    std::vector<int> m_specimen;  ///< per DOF: specimen index or -1
    std::vector<double> m_factor; ///< per DOF
};

} // namespace hsmu::comms
