#pragma once

// The watch table's rows as the tests reach them: device `row` of list `list` in the view's
// model (editor/watch_list_model.h), and the text a cell shows.

#include "editor/watch_list_view.h"

namespace rung::test {

inline QModelIndex watchIndex(const editor::WatchListView *view, int list, int row,
                              int column = editor::WatchListView::DeviceColumn) {
    const QAbstractItemModel *model = view->model();
    return model->index(row, column, model->index(list, 0));
}

inline QString watchText(const editor::WatchListView *view, int list, int row, int column) {
    return watchIndex(view, list, row, column).data().toString();
}

// The lists (list < 0), or the devices of a list.
inline int watchRows(const editor::WatchListView *view, int list = -1) {
    const QAbstractItemModel *model = view->model();
    return list < 0 ? model->rowCount() : model->rowCount(model->index(list, 0));
}

// The row of a device, in whichever list holds it first; invalid when none does.
inline QModelIndex watchRowOf(const editor::WatchListView *view, const QString &device) {
    for (int i = 0; i < watchRows(view); ++i)
        for (int k = 0; k < watchRows(view, i); ++k)
            if (watchText(view, i, k, editor::WatchListView::DeviceColumn) == device)
                return watchIndex(view, i, k);
    return {};
}

} // namespace rung::test
