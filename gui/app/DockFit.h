#pragma once
// A dock whose form sits in a scroll area (so it never grows the window past its design size)
// takes, each time it is shown docked, the width its form asks for, at most half the window,
// scrolled to the form's left edge (docs/rths.md, "The console's RTHS view").

class QDockWidget;
class QMainWindow;
class QScrollArea;

namespace hsmu::gui {

void fitDockToForm(QMainWindow& window, QDockWidget& dock, QScrollArea& scroll);

} // namespace hsmu::gui
