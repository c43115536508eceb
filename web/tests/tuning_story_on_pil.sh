#!/usr/bin/env bash
# The thesis' tuning story (tests/tuning_story_e2e.mjs) in headless Chromium on the bridge's page, against the robot's
# firmware on the emulated Cortex-M4 and the simulated robot: duet pil in lock-step (the firmware's time exact
# whatever the machine's pace), the release scenario, run until the story is told.
# Prints "skipped: ..." (ctest's skip pattern) when something it needs is not built.
# Usage: tuning_story_on_pil.sh DUET FIRMWARE SCENARIO ARTEFACTS
set -euo pipefail
duet=$1 firmware=$2 scenario=$3 artefacts=$4
web=$(cd "$(dirname "$0")/.." && pwd)
[[ -f $firmware ]] || { echo "skipped: no firmware image $firmware (build the m4-qemu preset)"; exit 0; }
[[ -f $web/dist/index.html && -d $web/node_modules/playwright-core ]] ||
  { echo "skipped: the front end is not built (cd web && npm ci && npm run build)"; exit 0; }

work=$(mktemp -d)
pil=
cleanup() {
  [[ -n $pil ]] && kill -INT "$pil" 2>/dev/null || true
  wait 2>/dev/null || true
  [[ -n ${E2E_KEEP:-} ]] && cp -r "$work" "$E2E_KEEP"
  rm -rf "$work"
}
trap cleanup EXIT

"$duet" pil "$firmware" --scenario "$scenario" --lock-step --duration 600 --xcp 127.0.0.1:0 --websocket 127.0.0.1:0 \
  >"$work/pil.out" 2>&1 &
pil=$!
for _ in $(seq 1 200); do
  page=$(grep -oE 'http://127.0.0.1:[0-9]+/' "$work/pil.out" | head -1 || true)
  [[ -n $page ]] && break
  sleep 0.1
done
[[ -n $page ]] || { echo "tuning_story_on_pil: duet pil printed no dashboard address:" >&2; cat "$work/pil.out" >&2; exit 1; }

status=0
node "$web/tests/tuning_story_e2e.mjs" --url "$page" --artefacts "$artefacts" --timeout-s 90 || status=$?
kill -INT "$pil" 2>/dev/null || true
wait "$pil" 2>/dev/null || true
pil=
echo "duet pil said:"
cat "$work/pil.out"
echo "screenshots in $artefacts"
exit "$status"
