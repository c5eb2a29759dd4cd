#!/usr/bin/env bash
# Renders the README pictures into docs/images/ with the samples (works on Mesa llvmpipe):
#   dam_break_ssf.jpg        pf_headless, screen-space fluid, mid dam break
#   dam_break_particles.jpg  pf_headless, debug particles coloured by speed, same frame
#   viewer.png               pf_viewer under xvfb-run (window + UI), via --screenshot
# and, with --video, out/media/dam_break.mp4 (H.264, needs ffmpeg).
# Options are passed to both pf_headless runs (e.g. --scene NAME).
set -euo pipefail
cd "$(dirname "$0")/.."
video=0
args=()
for a in "$@"; do
  if [ "$a" = "--video" ]; then video=1; else args+=("$a"); fi
done
scripts/build.sh
out=out/media
mkdir -p "$out" docs/images
frames=54   # 0.9 s into the dam break: the wave has hit the far wall
to_jpg() { ffmpeg -y -hide_banner -loglevel error -i "$1" -q:v 4 "$2"; }

build/samples/pf_headless --frames $frames --every $frames --size 960x540 --out "$out/ssf" "${args[@]}"
to_jpg "$out/ssf/frame_0001.png" docs/images/dam_break_ssf.jpg
build/samples/pf_headless --frames $frames --every $frames --size 960x540 --render particles \
  --out "$out/particles" "${args[@]}"
to_jpg "$out/particles/frame_0001.png" docs/images/dam_break_particles.jpg

if [ -x build/samples/pf_viewer ]; then
  xvfb-run -a -s '-screen 0 1280x720x24' build/samples/pf_viewer --size 1280x720 --frames $frames \
    --screenshot "$out/viewer.png"
  # 256-colour palette PNG: a fraction of the size, the UI stays crisp.
  ffmpeg -y -hide_banner -loglevel error -i "$out/viewer.png" \
    -vf "split[a][b];[a]palettegen=max_colors=256:stats_mode=full[p];[b][p]paletteuse=dither=sierra2_4a" \
    docs/images/viewer.png
fi

if [ $video = 1 ]; then
  build/samples/pf_headless --every 2 --size 960x540 --out "$out/video" --video "$out/dam_break.mp4" "${args[@]}"
fi
ls -l docs/images
