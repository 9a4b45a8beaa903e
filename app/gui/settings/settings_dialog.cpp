#include "gui/settings/settings_dialog.h"

#include "gui/settings/tunables.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QSpinBox>
#include <QVBoxLayout>

namespace microsim::gui::settings {

SettingsDialog::SettingsDialog(QWidget* parent) : QDialog(parent) {
  setWindowTitle(tr("Settings"));
  setObjectName(QStringLiteral("settingsDialog"));
  auto* form = new QFormLayout;
  for (const Tunable& t : Tunables::all()) {
    const QVariant current = Tunables::value(t.key);
    QWidget* editor = nullptr;
    if (t.type == Tunable::Type::Integer) {
      auto* spin = new QSpinBox(this);
      spin->setRange(t.minimum, t.maximum);
      spin->setValue(current.toInt());
      spin->setSpecialValueText(tr("Scene default"));
      editor = spin;
    } else {
      auto* combo = new QComboBox(this);
      for (const Choice& c : t.choices) {
        if (c.isOffered()) combo->addItem(c.label, c.value);
      }
      combo->setCurrentIndex(std::max(0, combo->findData(current.toString())));
      editor = combo;
    }
    QString help = t.help;
    if (t.needsRestart) help += QLatin1Char(' ') + tr("Takes effect at the next start.");
    editor->setToolTip(help);
    editor->setObjectName(t.key);
    form->addRow(t.label, editor);
    editors_.insert(t.key, editor);
  }
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
  connect(buttons, &QDialogButtonBox::accepted, this, [this] {
    store();
    accept();
  });
  connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
  auto* layout = new QVBoxLayout(this);
  layout->addLayout(form);
  layout->addWidget(buttons);
}

void SettingsDialog::store() const {
  for (auto it = editors_.begin(); it != editors_.end(); ++it) {
    if (auto* spin = qobject_cast<QSpinBox*>(it.value()))
      Tunables::setValue(it.key(), spin->value());
    else if (auto* combo = qobject_cast<QComboBox*>(it.value()))
      Tunables::setValue(it.key(), combo->currentData());
  }
}

}  // namespace microsim::gui::settings
