#pragma once

// The translation contexts of model/'s messages outside a class of their own, each
// declared once: a file's texts go through its context, ChecksTr::tr("..."). lupdate takes the
// context from the class a tr() call names, so each is a class, not an alias of one.

#include <QCoreApplication>

namespace rung::model {

struct AddressTr {
    Q_DECLARE_TR_FUNCTIONS(rung::model::Address)
};
struct ChecksTr {
    Q_DECLARE_TR_FUNCTIONS(rung::model::Checks)
};
struct CompareTr {
    Q_DECLARE_TR_FUNCTIONS(rung::model::Compare)
};
struct ConvertTr {
    Q_DECLARE_TR_FUNCTIONS(rung::model::Convert)
};
struct InstructionListTr {
    Q_DECLARE_TR_FUNCTIONS(rung::model::InstructionList)
};
struct LadderTextTr {
    Q_DECLARE_TR_FUNCTIONS(rung::model::LadderText)
};
struct PlcopenTr {
    Q_DECLARE_TR_FUNCTIONS(rung::model::Plcopen)
};
struct PortConfigTr {
    Q_DECLARE_TR_FUNCTIONS(rung::model::PortConfig)
};
struct PowerFlowTr {
    Q_DECLARE_TR_FUNCTIONS(rung::model::PowerFlow)
};
struct ProjectTr {
    Q_DECLARE_TR_FUNCTIONS(rung::model::Project)
};
struct TriggerTr {
    Q_DECLARE_TR_FUNCTIONS(rung::model::Trigger)
};
struct TypedListingTr {
    Q_DECLARE_TR_FUNCTIONS(rung::model::TypedListing)
};
struct ValueFormatTr {
    Q_DECLARE_TR_FUNCTIONS(rung::model::ValueFormat)
};

} // namespace rung::model
