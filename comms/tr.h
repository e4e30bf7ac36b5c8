#pragma once

// The translation contexts of comms/'s messages outside a class of their own, each
// declared once: a file's texts go through its context, RelayTr::tr("..."). lupdate takes the
// context from the class a tr() call names, so each is a class, not an alias of one.

#include <QCoreApplication>

namespace rung::comms {

struct RelayTr {
    Q_DECLARE_TR_FUNCTIONS(rung::comms::Relay)
};

} // namespace rung::comms
