#include "ui/messages.h"

#include <QWidget>

namespace fog::ui {

QMessageBox* showMessage(QWidget* parent, MessageKind kind, const QString& title, const QString& headline,
                         const QString& details) {
  // Kept (hidden) when closed, and reused for the next message.
  const QString name = kind == MessageKind::kError ? QStringLiteral("errorDialog") : QStringLiteral("infoDialog");
  QMessageBox* box = nullptr;
  if (parent) box = parent->findChild<QMessageBox*>(name, Qt::FindDirectChildrenOnly);
  if (!box) {
    box = new QMessageBox(parent);
    box->setObjectName(name);
    box->setWindowModality(Qt::NonModal);
    box->setStandardButtons(QMessageBox::Close);
    box->setIcon(kind == MessageKind::kError ? QMessageBox::Warning : QMessageBox::Information);
    // Selectable: the reason can be copied into a report or an e-mail.
    box->setTextInteractionFlags(Qt::TextSelectableByMouse | Qt::TextSelectableByKeyboard);
    box->setTextFormat(Qt::PlainText);
  }
  box->setWindowTitle(title);
  box->setText(headline);
  box->setInformativeText(displayUnits(details));
  box->show();
  box->raise();
  return box;
}

}  // namespace fog::ui
