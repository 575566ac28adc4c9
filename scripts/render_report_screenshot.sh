#!/usr/bin/env bash
# Render the traceability report to a PNG with headless Chromium and check the image is not
# trivial (blank or tiny).
#   scripts/render_report_screenshot.sh [reports/index.html] [reports/screenshot.png] [WIDTHxHEIGHT]
# Installs Debian's chromium if /usr/bin/chromium is missing (needs root and the network).
set -euo pipefail
html=${1:-reports/index.html}
png=${2:-reports/screenshot.png}
size=${3:-1400,2000}
size=${size/x/,}

[ -f "$html" ] || { echo "render_report_screenshot: $html not found" >&2; exit 2; }
if [ ! -x /usr/bin/chromium ]; then
    echo "render_report_screenshot: installing chromium (Debian package)" >&2
    if [ "$(id -u)" -eq 0 ]; then sudo=""; else sudo="sudo"; fi
    $sudo apt-get update >/dev/null &&
        DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y chromium >/dev/null ||
        { echo "render_report_screenshot: could not install chromium" >&2; exit 3; }
fi

url="file://$(cd "$(dirname "$html")" && pwd)/$(basename "$html")"
mkdir -p "$(dirname "$png")"
png_abs="$(cd "$(dirname "$png")" && pwd)/$(basename "$png")"
profile=$(mktemp -d)
trap 'rm -rf "$profile"' EXIT
rm -f "$png_abs"
timeout 120 /usr/bin/chromium --headless --no-sandbox --disable-gpu --disable-quic --no-first-run \
    --disable-background-networking --disable-component-update --disable-sync \
    --disable-dev-shm-usage --hide-scrollbars --user-data-dir="$profile" \
    --screenshot="$png_abs" --window-size="$size" "$url" >/dev/null 2>"$profile/chromium.log" || {
    echo "render_report_screenshot: chromium failed:" >&2; tail -n 5 "$profile/chromium.log" >&2; exit 4; }

# Non-trivial: a PNG of the requested size, not tiny, with more than a handful of colours.
/usr/bin/python3 - "$png_abs" "$size" <<'PY'
import struct, sys, zlib
path, size = sys.argv[1], sys.argv[2]
with open(path, "rb") as fh:
    data = fh.read()
if data[:8] != b"\x89PNG\r\n\x1a\n":
    sys.exit(f"{path}: not a PNG")
w, h = struct.unpack(">II", data[16:24])
exp_w, exp_h = (int(x) for x in size.split(","))
if (w, h) != (exp_w, exp_h):
    sys.exit(f"{path}: {w}x{h}, expected {exp_w}x{exp_h}")
if len(data) < 20000:
    sys.exit(f"{path}: only {len(data)} bytes: probably blank")
# Decode IDAT and count distinct pixel rows to reject a blank page.
bit_depth, colour = data[24], data[25]
raw, pos = b"", 8
while pos < len(data):
    (n,) = struct.unpack(">I", data[pos:pos + 4]); kind = data[pos + 4:pos + 8]
    if kind == b"IDAT":
        raw += data[pos + 8:pos + 8 + n]
    pos += 12 + n
pix = zlib.decompress(raw)
bpp = {2: 3, 6: 4}.get(colour, 1) * max(bit_depth // 8, 1)
stride = w * bpp + 1
rows = {pix[i * stride + 1:(i + 1) * stride] for i in range(0, h, 7)}
if len(rows) < 20:
    sys.exit(f"{path}: only {len(rows)} distinct sampled rows: looks blank")
print(f"{path}: {w}x{h}, {len(data)} bytes, {len(rows)} distinct sampled rows: OK")
PY
