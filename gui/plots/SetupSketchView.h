#pragma once
// SetupSketchView: a link2d specimen and its experimental setup drawn from the setup's
// geometry (docs/console.md, "Actuators and setup"): at rest dashed grey, and deformed by the
// element's measured basic deformations magnified by a stated round scale (the scale grows
// the largest displacement so far to about a tenth of the element's length; never below 1),
// updated live. Geometry from core (core/experimental/SetupSketch.h, eqs. K1-K3); this class
// only maps metres to pixels (one scale for x and y, y up) and paints. A setup without a 2-D
// drawing shows why, in words.
// Thread rules: GUI thread only.

#include "core/config/TestConfig.h"
#include "core/experimental/SetupSketch.h"
#include "core/experimental/setup/ExperimentalSetup.h"

#include <QStringList>
#include <QWidget>

#include <memory>

namespace hsmu::gui {

class SetupSketchView : public QWidget {
    Q_OBJECT
public:
    explicit SetupSketchView(QWidget* parent = nullptr);
    ~SetupSketchView() override;

    /// Show this specimen (its name, geometry and setup) at rest; a setup that cannot be built
    /// or drawn shows the reason. clear() shows nothing.
    void setSpecimen(const std::string& name, const Link2dSpec& spec);
    void clear();
    /// The measured basic deformations now (axial [m], shear [m], rotation [rad]); the scale
    /// follows the largest so far. Repaints (queued).
    void setDeformation(const Eigen::Vector3d& d);
    /// Back to rest, the largest displacement forgotten.
    void reset();

    /// What is drawn (empty segments when nothing is), for tests and the caption.
    const SetupSketch& rest() const { return m_rest; }
    const SetupSketch& deformed() const { return m_deformed; }
    double scale() const { return m_deformed.scale; }
    QString caption() const;

protected:
    void paintEvent(QPaintEvent* event) override;
    void changeEvent(QEvent* event) override;

private:
    void recompute();

    std::string m_name;
    Link2dGeometry m_geometry;
    std::unique_ptr<ExperimentalSetup> m_setup;
    QString m_problem;           ///< why nothing is drawn (the configuration's error, translated)
    QStringList m_actuatorNames; ///< the channels' configured names, setup order
    Eigen::Vector3d m_d = Eigen::Vector3d::Zero();
    double m_peak = 0.0; ///< [m] largest |d_axial|, |d_shear|, L |d_rot| so far
    SetupSketch m_rest, m_deformed;
};

} // namespace hsmu::gui
