#!/usr/bin/env bash
# Brings resources/translations/*.ts up to date with the GUI's strings
# (lupdate over ui/ and the GUI's main), keeping every existing translation;
# new strings appear as unfinished for a translator (Qt Linguist) to fill in.
#
# lupdate 5.15 does not understand C++17 nested namespaces, so it names the
# contexts "MainWindow" where the running program asks for
# "fog::ui::MainWindow"; the contexts are unqualified for lupdate and
# qualified again afterwards.
#
# The lupdate is Qt 6's (the default build's) where installed, else Qt 5's;
# both give the same .ts.
set -euo pipefail
cd "$(dirname "$0")/.."
lupdate=lupdate
for candidate in /usr/lib/qt6/bin/lupdate /usr/lib/qt6/libexec/lupdate; do
  if [[ -x $candidate ]]; then lupdate=$candidate; break; fi
done
for ts in resources/translations/*.ts; do
  sed -i -E 's#<name>fog::ui::([A-Za-z]+)</name>#<name>\1</name>#' "$ts"
  # (its complaint about every such context is expected and dropped)
  "$lupdate" -silent -no-obsolete -locations relative ui app/fogbench_gui.cpp -ts "$ts" 2>&1 |
    { grep -v 'Qualifying with unknown namespace/class' || true; } >&2
  # Qt's own contexts (QObject, QAbstractFileIconProvider: words of Qt's
  # dialogs ours carries) stay unqualified.
  sed -i -E 's#<name>([A-Z][A-Za-z]+)</name>#<name>fog::ui::\1</name>#; s#<name>fog::ui::(Q[A-Z][A-Za-z]+)</name>#<name>\1</name>#' "$ts"
  echo "$ts: $(grep -c '<source>' "$ts") strings, $(grep -c 'type="unfinished"' "$ts" || true) unfinished"
done
