#pragma once

// Toolbar icons drawn with the ladder's own strokes, so the palette looks like what it places
// and needs no icon theme (a plain Debian desktop or Xvfb has none).

#include <QIcon>

namespace rung::editor {

enum class ToolIcon {
    OpenContact,
    ClosedContact,
    ParallelContact,
    RisingContact,
    FallingContact,
    Coil,
    Instruction,
    HorizontalWire,
    VerticalLink,
    NewFile,
    OpenFile,
    SaveFile,
    Undo,
    Redo,
    Pointer, // the select tool: the palette's tools put away
};

QIcon toolIcon(ToolIcon icon);

} // namespace rung::editor
