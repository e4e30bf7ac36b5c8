#pragma once

// Qt's QAbstractItemModelTester over a model, its findings collected instead of printed: a
// test asserts that it found nothing (findings()), after whatever it did to the model.

#include <QAbstractItemModelTester>
#include <QMutex>
#include <QMutexLocker>
#include <QStringList>

#include <memory>

namespace rung::test {

class CheckedModel {
public:
    explicit CheckedModel(QAbstractItemModel *model) {
        current() = this;
        m_previous = qInstallMessageHandler(&CheckedModel::collect);
        // Warning: a finding is a message (collected here), not an abort or a QtTest failure.
        m_tester = std::make_unique<QAbstractItemModelTester>(
            model, QAbstractItemModelTester::FailureReportingMode::Warning);
    }
    ~CheckedModel() {
        m_tester.reset();
        qInstallMessageHandler(m_previous);
        current() = nullptr;
    }
    CheckedModel(const CheckedModel &) = delete;
    CheckedModel &operator=(const CheckedModel &) = delete;

    QStringList findings() const {
        QMutexLocker lock(&m_mutex);
        return m_findings;
    }

private:
    static CheckedModel *&current() {
        static CheckedModel *checked = nullptr;
        return checked;
    }
    static void collect(QtMsgType type, const QMessageLogContext &context, const QString &text) {
        CheckedModel *self = current();
        if (self && context.category && qstrcmp(context.category, "qt.modeltest") == 0) {
            QMutexLocker lock(&self->m_mutex);
            self->m_findings << text;
            return;
        }
        if (self && self->m_previous)
            self->m_previous(type, context, text);
    }

    QtMessageHandler m_previous = nullptr;
    mutable QMutex m_mutex;
    QStringList m_findings;
    std::unique_ptr<QAbstractItemModelTester> m_tester;
};

} // namespace rung::test
