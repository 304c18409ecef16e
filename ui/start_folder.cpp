#include "start_folder.hpp"

#include <QDir>
#include <QFileInfo>
#include <QStandardPaths>

namespace maris::ui {

QString startFolder(const QString& preferred) {
  if (!preferred.isEmpty() && QFileInfo(preferred).isDir()) return QFileInfo(preferred).absoluteFilePath();
  const QString documents = QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation);
  if (!documents.isEmpty() && QFileInfo(documents).isDir()) return documents;
  return QDir::homePath();
}

}  // namespace maris::ui
