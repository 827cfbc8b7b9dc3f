#!/usr/bin/env bash
# Regenerates the font fuzz target's seeds (fuzz/corpus/font/): DejaVu Sans and DejaVu Sans
# Mono from Debian's fonts-dejavu-core, cut by fonttools' pyftsubset (Debian package fonttools,
# only needed to run this script) to the few glyphs the seeds' texts use, so each seed is a
# couple of KB. A seed is the font_fuzz input layout: options byte, text length, text, font.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
out="$root/fuzz/corpus/font"
command -v pyftsubset >/dev/null || { echo "needs pyftsubset: apt-get install fonttools" >&2; exit 1; }
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
mkdir -p "$out"

# seed NAME FONT TEXT OPTIONS: OPTIONS bit 0 = centre lines, bits 1-2 = tolerance choice.
seed() {
  local name="$1" font="$2" text="$3" options="$4"
  # Hinting and layout tables dropped: the outlines, cmap and metrics are what we read.
  pyftsubset "/usr/share/fonts/truetype/dejavu/$font" --text="$text" --no-hinting \
    --layout-features='' --drop-tables+=FFTM,GDEF,GPOS,GSUB --output-file="$tmp/$name.ttf"
  { printf "\\x$(printf %02x "$options")\\x$(printf %02x "${#text}")%s" "$text"
    cat "$tmp/$name.ttf"; } >"$out/$name"
}
seed outline-QD DejaVuSans.ttf QD 0
seed centerline-L DejaVuSans.ttf L 1
seed outline-fine-O DejaVuSans.ttf O 2
seed mono-two-lines DejaVuSansMono.ttf 'A
B' 6
ls -l "$out"
