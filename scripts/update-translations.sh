#!/usr/bin/env bash
# Refresh every catalogue in translations/ from today's gui/ sources (Qt 6's lupdate), and
# keep the English source catalogue complete (its translation of each string is the string).
# New strings then show as unfinished in the other catalogues until someone translates them
# (Qt Linguist: /usr/lib/qt6/bin/linguist, or any editor); test_gui_translations fails until then.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
lupdate=/usr/lib/qt6/bin/lupdate
[ -x "$lupdate" ] || { echo "update-translations: $lupdate missing (qt6-l10n-tools)" >&2; exit 1; }
cd "$here"
for ts in translations/hsmu_*.ts "$@"; do
  "$lupdate" -silent -no-obsolete -locations none -I . gui -ts "$ts"
done
python3 scripts/fill-english-catalogue.py translations/hsmu_en.ts
