#pragma once

// Answering the modal dialogs a GUI action opens, as a user would: a timer finds the dialog
// in front and hands it to the test's answer.

#include <QApplication>
#include <QTimer>
#include <QWidget>

#include <functional>

namespace rung::test {

// Answers the modal dialogs that open while `run` runs, each with `answer`, which returns true
// once it has closed the dialog.
inline void answerDialogs(const std::function<bool(QWidget *)> &answer,
                          const std::function<void()> &run) {
    QTimer timer;
    timer.setInterval(5);
    QObject::connect(&timer, &QTimer::timeout, [&answer] {
        if (QWidget *modal = QApplication::activeModalWidget())
            answer(modal);
    });
    timer.start();
    run();
    timer.stop();
}

} // namespace rung::test
