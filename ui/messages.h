#pragma once
// Messages the operator must read whole: a failed run, a session that cannot
// be opened, a refused import, a confirmation of an action they asked for.
// They appear in a non-modal message box (an unattended window never blocks
// on one) whose text is complete and selectable, so that it can be copied
// into a report or an e-mail. One box per kind and parent: a newer message
// replaces the text of a box still open instead of piling up windows.

#include <QMessageBox>
#include <QString>

#include "ui/core_text.h"  // displayUnits

namespace fog::ui {

enum class MessageKind {
  kError,        // object name "errorDialog", warning icon
  kInformation,  // object name "infoDialog", information icon
};

// Shows `headline` (one line: what happened) and `details` (the whole reason
// and what to do) in a non-modal box owned by `parent`; returns the box.
QMessageBox* showMessage(QWidget* parent, MessageKind kind, const QString& title, const QString& headline,
                         const QString& details);


}  // namespace fog::ui
