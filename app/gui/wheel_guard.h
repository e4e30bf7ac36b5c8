#pragma once

// Settings the mouse wheel cannot change in passing. Scrolling a dock with the wheel passes
// over its combo boxes and spin boxes; Qt lets each take the wheel, so a format 7E1 became
// 8N2 and a station 0 became 2 without a word (issue 31). Guarded, a wheel over a closed
// combo box, or over a spin box the user has not clicked into, scrolls the dock instead; a
// spin box with the keyboard focus still takes it, as the user asked for it.

class QWidget;

namespace rung::app {

// Guards every combo box and spin box inside `root` now (children added later are not).
void guardWheel(QWidget *root);

} // namespace rung::app
