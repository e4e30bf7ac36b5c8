#pragma once

// A file with this content in a temporary folder, for the tests that open what a user has.

#include <QByteArray>
#include <QFile>
#include <QTemporaryDir>

#include <gtest/gtest.h>

namespace rung::test {

inline QString writeFile(const QTemporaryDir &dir, const QString &name, const QByteArray &content) {
    const QString path = dir.filePath(name);
    QFile f(path);
    EXPECT_TRUE(f.open(QIODevice::WriteOnly)) << path.toStdString();
    EXPECT_EQ(f.write(content), content.size()) << path.toStdString();
    return path;
}

} // namespace rung::test
