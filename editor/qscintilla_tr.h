#pragma once

#include <QtGlobal>

// QScintilla builds its context menu with QsciScintilla::tr() and ships no Hungarian or
// Italian catalogue. Naming the texts here makes lupdate put them into our .ts files under
// the "QsciScintilla" context, so our translator answers them. The texts must stay exactly
// as QScintilla writes them (libqscintilla2_qt6 15.x).
namespace rung::editor::qscintillaTexts {
inline constexpr const char *contextMenu[] = {
    QT_TRANSLATE_NOOP("QsciScintilla", "&Undo"),      QT_TRANSLATE_NOOP("QsciScintilla", "&Redo"),
    QT_TRANSLATE_NOOP("QsciScintilla", "Cu&t"),       QT_TRANSLATE_NOOP("QsciScintilla", "&Copy"),
    QT_TRANSLATE_NOOP("QsciScintilla", "&Paste"),     QT_TRANSLATE_NOOP("QsciScintilla", "Delete"),
    QT_TRANSLATE_NOOP("QsciScintilla", "Select All"),
};
} // namespace rung::editor::qscintillaTexts
