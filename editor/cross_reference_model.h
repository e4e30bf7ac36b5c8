#pragma once

// The cross reference as a tree model: a row per device (its name from the symbol table, how
// often it is a contact, a coil or in a box, its comment), under it a row per use (rung, step,
// use, instruction), and when the uses run past the limit a last row that says so. The filter
// (a device, a prefix or nothing) and the limit are the model's; the uses come from
// model::crossReference. It follows the document at once only while following (a view on
// screen): else a change marks it stale, and it catches up when following again, so a large
// program edits as fast with it as without.

#include "model/listing/cross_reference.h"

#include <QAbstractItemModel>

namespace rung::editor {

class Document;

class CrossReferenceModel : public QAbstractItemModel {
    Q_OBJECT

public:
    enum Column { DeviceColumn, StepColumn, UseColumn, InstructionColumn, ColumnCount };
    enum Role {
        DeviceRole = Qt::UserRole + 1, // a device's or a use's device, as the target writes it
        RungRole,                      // a use's rung (0-based); none on a device's row
    };
    static constexpr int kMaxUses = 5000;

    explicit CrossReferenceModel(Document *document, QObject *parent = nullptr);

    QString filter() const { return m_filter; }
    void setFilter(const QString &filter); // lists anew, whether following or not
    int maxUses() const { return m_maxUses; }
    void setMaxUses(int maxUses);
    bool following() const { return m_following; }
    void setFollowing(bool following);
    bool isStale() const { return m_stale; }
    void refresh(); // the uses again, from the document as it is now
    // The headers and the rows' words in the language now installed.
    void retranslate();

    const model::CrossReference &uses() const { return m_uses; }
    bool capped() const { return m_uses.capped; }
    // The filter names one device, not a prefix.
    bool exact() const { return m_uses.exact; }
    // The row that says the list stops at the limit (capped() only).
    bool isNote(const QModelIndex &index) const;

    QModelIndex index(int row, int column, const QModelIndex &parent = {}) const override;
    QModelIndex parent(const QModelIndex &child) const override;
    int rowCount(const QModelIndex &parent = {}) const override;
    int columnCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation,
                        int role = Qt::DisplayRole) const override;
    Qt::ItemFlags flags(const QModelIndex &index) const override;
    // A device's row or a use drags its device to the watch table or the timing chart.
    QStringList mimeTypes() const override;
    QMimeData *mimeData(const QModelIndexList &indexes) const override;
    Qt::DropActions supportedDragActions() const override { return Qt::CopyAction; }

private:
    const model::CrossReference::Device *deviceOf(const QModelIndex &index) const;
    QVariant deviceData(const model::CrossReference::Device &device, int column, int role) const;
    QVariant useData(const model::CrossReference::Use &use, int column, int role) const;
    QString summary(const model::CrossReference::Device &device) const;
    static QString word(model::DeviceUse use); // "contact", "coil", "box"

    Document *m_document;
    QString m_filter;
    int m_maxUses = kMaxUses;
    model::CrossReference m_uses;
    bool m_following = false;
    bool m_stale = true;
};

} // namespace rung::editor
