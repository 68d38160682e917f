#!/usr/bin/env bash
# Builds the web playground into web/www/ (then serve that folder:
# `python3 -m http.server -d web/www 8000`):
#
#   www/pkg/      the engine compiled to wasm32-unknown-unknown (release)
#                 and the wasm-bindgen glue (ES module, --target web)
#   www/native.json  what the native CLI computes for the same inputs: each
#                 built-in scene's hash after SCENE_TICKS ticks, and the
#                 determinism panel's run (DETERMINISM_SCENE with the
#                 scripted input of seed DETERMINISM_SEED for
#                 DETERMINISM_TICKS ticks, via `clockwork2d record`)
#
# Installs what it lacks: the rustup target, and wasm-bindgen-cli at exactly
# the version of the wasm-bindgen crate in Cargo.lock (`cargo install
# --locked`, a compile from source; no prebuilt download).
# Honours CARGO_TARGET_DIR. Prints the .wasm size (raw and gzip -9).
set -euo pipefail
cd "$(dirname "$0")/.."
ROOT=$PWD
SECONDS=0

WASM_BINDGEN_VERSION=0.2.129
SCENE_TICKS=300
DETERMINISM_SCENE=mixed
DETERMINISM_SEED=16
DETERMINISM_TICKS=600

TARGET_DIR=${CARGO_TARGET_DIR:-$ROOT/target}
case $TARGET_DIR in /*) ;; *) TARGET_DIR=$ROOT/$TARGET_DIR ;; esac
OUT=$ROOT/web/www
log() { printf '== web: %s (%ds)\n' "$*" "$SECONDS"; }
die() {
  printf 'web/build.sh: %s\n' "$*" >&2
  exit 1
}

# The crate and the CLI must agree on the wasm-bindgen version: the glue the
# CLI writes reads a schema the crate's macros embed in the module.
locked=$(awk '/^name = "wasm-bindgen"$/ { getline; sub(/^version = "/, ""); sub(/"$/, ""); print }' Cargo.lock)
[[ $locked == "$WASM_BINDGEN_VERSION" ]] ||
  die "Cargo.lock has wasm-bindgen $locked but this script installs $WASM_BINDGEN_VERSION: change both together"

if ! rustup target list --installed | grep -qx wasm32-unknown-unknown; then
  log "rustup target add wasm32-unknown-unknown"
  rustup target add wasm32-unknown-unknown
fi
if [[ $(wasm-bindgen --version 2>/dev/null || true) != "wasm-bindgen $WASM_BINDGEN_VERSION" ]]; then
  log "cargo install wasm-bindgen-cli $WASM_BINDGEN_VERSION"
  cargo install wasm-bindgen-cli --version "$WASM_BINDGEN_VERSION" --locked
fi

log "cargo build (wasm32-unknown-unknown, release)"
cargo build -p clockwork2d-web --release --target wasm32-unknown-unknown
WASM=$TARGET_DIR/wasm32-unknown-unknown/release/clockwork2d_web.wasm
rm -rf "$OUT/pkg"
wasm-bindgen --target web --no-typescript --out-dir "$OUT/pkg" "$WASM"

log "native hashes (clockwork2d CLI, release)"
# The workspace's selection (no -p), as `cargo run --release` builds it: the
# same feature set, so the binary CI's main job built is reused, not rebuilt.
cargo build --release --bin clockwork2d
CLI=$TARGET_DIR/release/clockwork2d
final_hash() { sed -n 's/^.*final.* hash \(0x[0-9a-f]\{16\}\).*/\1/p'; }
scenes_json=""
for scene in $("$CLI" scenes); do
  hash=$("$CLI" run "$scene" --ticks "$SCENE_TICKS" --hash-every 0 | final_hash)
  [[ -n $hash ]] || die "no hash from clockwork2d run $scene"
  scenes_json+="${scenes_json:+,}\"$scene\":\"$hash\""
done
replay=$(mktemp "${TMPDIR:-/tmp}/web-determinism.XXXXXX")
trap 'rm -f "$replay"' EXIT
det_hash=$("$CLI" record "$DETERMINISM_SCENE" --ticks "$DETERMINISM_TICKS" \
  --seed "$DETERMINISM_SEED" --hash-every "$DETERMINISM_TICKS" -o "$replay" | final_hash)
[[ -n $det_hash ]] || die "no hash from clockwork2d record"
cat >"$OUT/native.json" <<JSON
{
  "scene_ticks": $SCENE_TICKS,
  "scenes": {$scenes_json},
  "determinism": {"scene": "$DETERMINISM_SCENE", "seed": $DETERMINISM_SEED, "ticks": $DETERMINISM_TICKS, "hash": "$det_hash"},
  "rustc": "$(rustc --version)"
}
JSON

bytes=$(stat -c %s "$OUT/pkg/clockwork2d_web_bg.wasm")
gz=$(gzip -9 -c "$OUT/pkg/clockwork2d_web_bg.wasm" | wc -c)
log "done: web/www/pkg/clockwork2d_web_bg.wasm $bytes bytes ($gz gzip -9)"
