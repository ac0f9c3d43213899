# Regenerate python/sarkp/listings/ from the book's OCR text: conv.py transcribes each
# listing (table.py: its book lines) and marks the mechanical OCR fixes; fixes.py applies the
# hand-made corrections, each with its "C OCR:" mark; index.py writes index.csv.
# Usage: bash scripts/listings_from_ocr/build.sh   (needs ../shared/seeds/ of the project)
set -e
HERE=$(cd "$(dirname "$0")" && pwd)
DEST=$HERE/../../python/sarkp/listings
TMP=$(mktemp -d)
cd "$HERE"
python3 conv.py "$TMP" > "$TMP/warnings.txt"
python3 fixes.py "$TMP"
rm -f "$DEST"/*.f
cp "$TMP"/*.f "$DEST"/
python3 index.py "$DEST/index.csv"
rm -rf "$TMP"
