// Where file dialogs start: a folder that exists, so the dialog never opens on a missing path.
#pragma once

#include <QString>

namespace maris::ui {

// `preferred` (typically the folder used last) if it is an existing folder; else the user's
// documents folder if it exists; else the home folder.
QString startFolder(const QString& preferred);

}  // namespace maris::ui
