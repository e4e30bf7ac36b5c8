// The cross reference's model alone, without its view: a row per device and under it a row
// per use, each column's text, the filter by a device and by a prefix, the limit of uses and
// its note, following the document only while asked to, the devices a drag carries, and the
// model's signals as Qt's model tester checks them.

#include "editor/cross_reference_model.h"
#include "editor/device_mime.h"
#include "editor/document.h"

#include "tests/editor/model_tester.h"

#include <QMimeData>
#include <QSignalSpy>

#include <gtest/gtest.h>

#include <memory>

using namespace rung;
using editor::CrossReferenceModel;

namespace {

struct CrossReferenceModelTest : ::testing::Test {
    CrossReferenceModelTest() {
        document.reset(model::Target::get(model::Family::Vigor), QStringLiteral("VB"));
        program(QStringLiteral("LD X0\nOUT Y0\nLD Y0\nANI X1\nOUT Y1\nLD M0\nTMR T0 K10\nEND\n"));
    }
    void program(const QString &text) {
        std::vector<model::Diagnostic> errors;
        ASSERT_TRUE(document.setListing(text, &errors));
    }
    model::Address device(const char *text) const {
        return std::get<model::Address>(
            model::parseAddress(document.target(), QString::fromLatin1(text)));
    }
    // The devices listed, in their order, as the first column names them.
    QStringList devices() const {
        QStringList out;
        for (int r = 0; r < uses.rowCount(); ++r)
            if (!uses.isNote(uses.index(r, 0)))
                out << uses.index(r, 0).data(CrossReferenceModel::DeviceRole).toString();
        return out;
    }
    QString text(int row, int column, const QModelIndex &parent = {},
                 int role = Qt::DisplayRole) const {
        return uses.index(row, column, parent).data(role).toString();
    }

    editor::Document document;
    CrossReferenceModel uses{&document};
};

} // namespace

TEST_F(CrossReferenceModelTest, ADeviceRowSaysItsNameUsesAndCommentAndAUseRowWhereAndHow) {
    document.setSymbols({{device("Y0"), QStringLiteral("Pump"), QStringLiteral("main pump")}});
    uses.setFilter(QString());
    EXPECT_EQ(devices(),
              (QStringList{QStringLiteral("X0"), QStringLiteral("X1"), QStringLiteral("Y0"),
                           QStringLiteral("Y1"), QStringLiteral("M0"), QStringLiteral("T0")}));
    EXPECT_EQ(uses.columnCount(), 4);
    const QString titles[] = {QStringLiteral("Device"), QStringLiteral("Step"),
                              QStringLiteral("Use"), QStringLiteral("Instruction")};
    for (int c = 0; c < 4; ++c)
        EXPECT_EQ(uses.headerData(c, Qt::Horizontal).toString(), titles[c]);

    const int y0Row = static_cast<int>(devices().indexOf(QStringLiteral("Y0")));
    const QModelIndex y0 = uses.index(y0Row, 0);
    EXPECT_EQ(text(y0Row, 0), QStringLiteral("Y0  Pump"));
    EXPECT_EQ(text(y0Row, 0, {}, Qt::ToolTipRole), QStringLiteral("Y0  Pump"));
    EXPECT_TRUE(text(y0Row, 1).isEmpty());
    EXPECT_EQ(text(y0Row, 2), QStringLiteral("1 × contact, 1 × coil"));
    EXPECT_EQ(text(y0Row, 3), QStringLiteral("main pump"));
    EXPECT_FALSE(y0.data(CrossReferenceModel::RungRole).isValid());
    ASSERT_EQ(uses.rowCount(y0), 2);
    // OUT Y0, step 1 of rung 1; LD Y0, step 2 of rung 2.
    const QString out[] = {QStringLiteral("rung 1"), QStringLiteral("0001"), QStringLiteral("coil"),
                           QStringLiteral("OUT Y0")};
    const QString load[] = {QStringLiteral("rung 2"), QStringLiteral("0002"),
                            QStringLiteral("contact"), QStringLiteral("LD Y0")};
    for (int c = 0; c < 4; ++c) {
        EXPECT_EQ(text(0, c, y0), out[c]);
        EXPECT_EQ(text(1, c, y0), load[c]);
    }
    EXPECT_EQ(uses.index(0, 0, y0).data(CrossReferenceModel::RungRole).toInt(), 0);
    EXPECT_EQ(uses.index(1, 3, y0).data(CrossReferenceModel::RungRole).toInt(), 1);
    EXPECT_EQ(uses.index(1, 2, y0).data(CrossReferenceModel::DeviceRole).toString(),
              QStringLiteral("Y0"));
    EXPECT_EQ(uses.parent(uses.index(1, 2, y0)), y0);
    EXPECT_EQ(uses.rowCount(uses.index(1, 0, y0)), 0);
    // A device without a symbol is its address; a box's use.
    const int t0Row = static_cast<int>(devices().indexOf(QStringLiteral("T0")));
    EXPECT_EQ(text(t0Row, 0), QStringLiteral("T0"));
    EXPECT_TRUE(text(t0Row, 3).isEmpty());
    EXPECT_EQ(text(0, 2, uses.index(t0Row, 0)), QStringLiteral("box"));
    EXPECT_EQ(text(0, 3, uses.index(t0Row, 0)), QStringLiteral("TMR T0 K10"));
    EXPECT_EQ(text(t0Row, 2), QStringLiteral("1 × box"));
}

TEST_F(CrossReferenceModelTest, TheFilterTakesADeviceOrAPrefixOfTheDevices) {
    uses.setFilter(QStringLiteral("X0"));
    EXPECT_TRUE(uses.exact());
    EXPECT_EQ(devices(), QStringList{QStringLiteral("X0")});
    uses.setFilter(QStringLiteral(" x "));
    EXPECT_FALSE(uses.exact());
    EXPECT_EQ(devices(), (QStringList{QStringLiteral("X0"), QStringLiteral("X1")}));
    uses.setFilter(QStringLiteral("Y1"));
    EXPECT_EQ(devices(), QStringList{QStringLiteral("Y1")});
    uses.setFilter(QStringLiteral("X7")); // a device nothing uses
    EXPECT_TRUE(uses.exact());
    EXPECT_EQ(uses.rowCount(), 0);
    uses.setFilter(QStringLiteral("Q"));
    EXPECT_EQ(uses.rowCount(), 0);
    uses.setFilter(QString());
    EXPECT_EQ(devices().size(), 6);
    EXPECT_EQ(uses.filter(), QString());
}

TEST_F(CrossReferenceModelTest, TheUsesStopAtTheLimitAndALastRowSaysSo) {
    uses.setFilter(QString());
    EXPECT_EQ(uses.uses().uses, 7);
    EXPECT_FALSE(uses.capped());
    uses.setMaxUses(7); // all of them: nothing left out, no note
    EXPECT_FALSE(uses.capped());
    EXPECT_EQ(uses.rowCount(), 6);
    uses.setMaxUses(3);
    ASSERT_TRUE(uses.capped());
    EXPECT_EQ(uses.uses().uses, 3);
    // X0 (LD X0), Y0 (OUT Y0, LD Y0): the first three in program order.
    EXPECT_EQ(devices(), (QStringList{QStringLiteral("X0"), QStringLiteral("Y0")}));
    ASSERT_EQ(uses.rowCount(), 3);
    const QModelIndex note = uses.index(2, 0);
    EXPECT_TRUE(uses.isNote(note));
    EXPECT_EQ(note.data().toString(),
              QStringLiteral("The first 3 uses; type a device or a prefix for the rest"));
    EXPECT_EQ(uses.rowCount(note), 0);
    EXPECT_FALSE(uses.flags(note) & Qt::ItemIsSelectable);
    EXPECT_FALSE(uses.index(2, 1).data().isValid());
    EXPECT_FALSE(note.data(CrossReferenceModel::DeviceRole).isValid());
    // A filter narrows what the limit counts.
    uses.setFilter(QStringLiteral("Y"));
    EXPECT_FALSE(uses.capped());
    EXPECT_EQ(devices(), (QStringList{QStringLiteral("Y0"), QStringLiteral("Y1")}));
    EXPECT_EQ(CrossReferenceModel::kMaxUses, 5000);
}

TEST_F(CrossReferenceModelTest, ItFollowsTheDocumentOnlyWhileFollowingAndCatchesUpAfter) {
    uses.setFilter(QString());
    ASSERT_FALSE(uses.following());
    QSignalSpy reset(&uses, &QAbstractItemModel::modelReset);
    program(QStringLiteral("LD X6\nOUT Y6\nEND\n"));
    EXPECT_TRUE(reset.isEmpty()); // out of sight: left alone
    EXPECT_TRUE(uses.isStale());
    EXPECT_EQ(devices().size(), 6);
    uses.setFollowing(true); // back in sight: it catches up
    EXPECT_EQ(reset.size(), 1);
    EXPECT_FALSE(uses.isStale());
    EXPECT_EQ(devices(), (QStringList{QStringLiteral("X6"), QStringLiteral("Y6")}));
    program(QStringLiteral("LD X5\nOUT Y5\nEND\n")); // in sight: at once
    EXPECT_EQ(reset.size(), 2);
    EXPECT_EQ(devices(), (QStringList{QStringLiteral("X5"), QStringLiteral("Y5")}));
    // A symbol named follows too (its name is in the device's row).
    document.setSymbols({{device("Y5"), QStringLiteral("Lamp"), QString()}});
    EXPECT_EQ(text(1, 0), QStringLiteral("Y5  Lamp"));
    document.undoStack()->undo();
    EXPECT_EQ(text(1, 0), QStringLiteral("Y5"));
}

TEST_F(CrossReferenceModelTest, ADeviceOrAUseDragsItsDevice) {
    uses.setFilter(QString());
    const QModelIndex x0 = uses.index(0, 0);
    const QModelIndex y0 = uses.index(2, 0);
    EXPECT_TRUE(uses.flags(x0) & Qt::ItemIsDragEnabled);
    EXPECT_TRUE(uses.flags(uses.index(1, 3, y0)) & Qt::ItemIsDragEnabled);
    EXPECT_EQ(uses.mimeTypes(), QStringList{editor::deviceMimeType()});
    std::unique_ptr<QMimeData> data(
        uses.mimeData({uses.index(1, 0, y0), uses.index(1, 3, y0), x0}));
    ASSERT_NE(data, nullptr);
    EXPECT_EQ(editor::devicesFromMime(data.get()),
              (QStringList{QStringLiteral("Y0"), QStringLiteral("X0")}));
}

TEST_F(CrossReferenceModelTest, QtsModelTesterFindsNothingThroughFiltersEditsAndTheLimit) {
    test::CheckedModel checked(&uses);
    uses.setFilter(QString());
    uses.setFilter(QStringLiteral("X"));
    uses.setFilter(QStringLiteral("Y0"));
    uses.setFollowing(true);
    program(QStringLiteral("LD X0\nOUT Y0\nLD Y0\nOR Y1\nOUT Y1\nEND\n"));
    uses.setFilter(QString());
    uses.setMaxUses(2);
    uses.retranslate();
    document.setSymbols({{device("Y1"), QStringLiteral("Horn"), QStringLiteral("loud")}});
    uses.setMaxUses(CrossReferenceModel::kMaxUses);
    document.undoStack()->undo();
    uses.setFollowing(false);
    program(QStringLiteral("END\n"));
    uses.setFollowing(true);
    EXPECT_EQ(uses.rowCount(), 0);
    EXPECT_TRUE(checked.findings().isEmpty()) << checked.findings().join(u'\n').toStdString();
}
