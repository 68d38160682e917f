#!/usr/bin/env bash
# Bit-identical on five architectures, in debug and release (issue 6).
#
# Builds the determinism suite's runner (the determinism/ crate's example
# determinism_suite, determinism/examples/determinism_suite.rs) once per
# target and profile and runs it; every run must reproduce every golden hash
# of determinism/src/golden.rs:
#
#   x86_64-unknown-linux-gnu   natively, and again with -C target-cpu=native
#   i686-unknown-linux-gnu     32-bit (natively through the cross ld.so when
#                              the kernel runs 32-bit code, else qemu-i386)
#   aarch64-unknown-linux-gnu  qemu-aarch64 -L /usr/aarch64-linux-gnu
#   s390x-unknown-linux-gnu    big-endian, qemu-s390x -L /usr/s390x-linux-gnu
#   wasm32-wasip1              Node's node:wasi (scripts/wasi-run.mjs)
#
# each in debug (overflow checks on) and release. Snapshot and replay files
# cross architectures too: x86_64 (release) writes a replay and a mid-run
# snapshot per scene, s390x (release) verifies them and writes its own, and
# every other run verifies both sets.
#
# Installs what it needs (rustup targets; Debian's qemu-user and gcc cross
# linkers), prints a table target x profile x scene with ok/MISMATCH, and
# exits non-zero on any mismatch or failed build. Linkers and runners are
# also in .cargo/config.toml for `cargo run --target ...` by hand.
#
# Honours CARGO_TARGET_DIR (default ./target); the target-cpu=native build
# uses its own directory under it so it does not invalidate the others.
set -euo pipefail
cd "$(dirname "$0")/.."
ROOT=$PWD
SECONDS=0

TARGET_DIR=${CARGO_TARGET_DIR:-$ROOT/target}
case $TARGET_DIR in /*) ;; *) TARGET_DIR=$ROOT/$TARGET_DIR ;; esac
export CARGO_TARGET_DIR=$TARGET_DIR
NATIVE_CPU_DIR=$TARGET_DIR/native-cpu
HOST=$(rustc -vV | sed -n 's/^host: //p')
CROSS_TARGETS=(i686-unknown-linux-gnu aarch64-unknown-linux-gnu s390x-unknown-linux-gnu wasm32-wasip1)
PROFILES=(release debug)

WORK=$(mktemp -d "${TMPDIR:-/tmp}/cross-determinism.XXXXXX")
trap 'rm -rf "$WORK"' EXIT
FILES_X86=$WORK/files-x86_64
FILES_S390X=$WORK/files-s390x

log() { printf '== %s (%ds)\n' "$*" "$SECONDS"; }
die() {
  printf 'cross-determinism: %s\n' "$*" >&2
  exit 1
}

# --- install ----------------------------------------------------------------

install_tools() {
  local missing=()
  command -v qemu-aarch64 >/dev/null || missing+=(qemu-user)
  command -v qemu-s390x >/dev/null || missing+=(qemu-user)
  command -v qemu-i386 >/dev/null || missing+=(qemu-user)
  command -v i686-linux-gnu-gcc >/dev/null || missing+=(gcc-i686-linux-gnu)
  command -v aarch64-linux-gnu-gcc >/dev/null || missing+=(gcc-aarch64-linux-gnu)
  command -v s390x-linux-gnu-gcc >/dev/null || missing+=(gcc-s390x-linux-gnu)
  # The C libraries the cross linkers link against (also pulled in by the
  # gcc packages; named so a partial install is completed).
  [[ -e /usr/i686-linux-gnu/lib/libc.so.6 ]] || missing+=(libc6-dev-i386-cross)
  [[ -e /usr/aarch64-linux-gnu/lib/libc.so.6 ]] || missing+=(libc6-dev-arm64-cross)
  [[ -e /usr/s390x-linux-gnu/lib/libc.so.6 ]] || missing+=(libc6-dev-s390x-cross)
  command -v node >/dev/null || missing+=(nodejs)
  if ((${#missing[@]} > 0)); then
    local sudo=()
    [[ $(id -u) == 0 ]] || sudo=(sudo)
    log "apt-get install ${missing[*]}"
    "${sudo[@]}" apt-get update -qq
    DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get install -y -qq --no-install-recommends \
      $(printf '%s\n' "${missing[@]}" | sort -u) >/dev/null
  fi
  local installed
  installed=$(rustup target list --installed)
  for t in "${CROSS_TARGETS[@]}"; do
    if ! grep -qx "$t" <<<"$installed"; then
      log "rustup target add $t"
      rustup target add "$t"
    fi
  done
  local node_major
  node_major=$(node -p 'process.versions.node.split(".")[0]')
  ((node_major >= 20)) || die "node $node_major is too old for node:wasi without flags (need >= 20)"
}

# --- build ------------------------------------------------------------------

# The suite binary of a target and profile.
binary() {
  local target=$1 profile=$2
  case $target in
    native-cpu) echo "$NATIVE_CPU_DIR/$profile/examples/determinism_suite" ;;
    "$HOST") echo "$TARGET_DIR/$profile/examples/determinism_suite" ;;
    wasm32-wasip1) echo "$TARGET_DIR/$target/$profile/examples/determinism_suite.wasm" ;;
    *) echo "$TARGET_DIR/$target/$profile/examples/determinism_suite" ;;
  esac
}

build() {
  local target=$1 profile=$2
  local args=(build --quiet -p clockwork2d-determinism --example determinism_suite)
  [[ $profile == release ]] && args+=(--release)
  log "build $target $profile"
  case $target in
    native-cpu)
      CARGO_TARGET_DIR=$NATIVE_CPU_DIR RUSTFLAGS="${RUSTFLAGS:-} -C target-cpu=native" \
        cargo "${args[@]}"
      ;;
    "$HOST") cargo "${args[@]}" ;;
    *) cargo "${args[@]}" --target "$target" ;;
  esac
  [[ -f $(binary "$target" "$profile") ]] || die "build of $target $profile produced no binary"
}

# --- run --------------------------------------------------------------------

I686_RUNNER=()
pick_i686_runner() {
  local loader=/usr/i686-linux-gnu/lib/ld-linux.so.2 bin
  bin=$(binary i686-unknown-linux-gnu release)
  if "$loader" --library-path /usr/i686-linux-gnu/lib "$bin" --list >/dev/null 2>&1; then
    I686_RUNNER=("$loader" --library-path /usr/i686-linux-gnu/lib)
    echo "i686: runs natively (32-bit code on the x86_64 kernel, cross ld.so)"
  else
    I686_RUNNER=(qemu-i386 -L /usr/i686-linux-gnu)
    echo "i686: runs under qemu-i386"
  fi
}

label_of() {
  case $1 in
    native-cpu) echo "$HOST+cpu=native" ;;
    *) echo "$1" ;;
  esac
}

ROWS=$WORK/rows
: >"$ROWS"
FAILED_RUNS=()

# run TARGET PROFILE [suite args...]
run() {
  local target=$1 profile=$2
  shift 2
  local bin runner=() out status=0
  bin=$(binary "$target" "$profile")
  case $target in
    i686-unknown-linux-gnu) runner=("${I686_RUNNER[@]}") ;;
    aarch64-unknown-linux-gnu) runner=(qemu-aarch64 -L /usr/aarch64-linux-gnu) ;;
    s390x-unknown-linux-gnu) runner=(qemu-s390x -L /usr/s390x-linux-gnu) ;;
    wasm32-wasip1) runner=(node --no-warnings "$ROOT/scripts/wasi-run.mjs" --dir "$WORK") ;;
  esac
  out=$WORK/out-$(label_of "$target")-$profile
  log "run $(label_of "$target") $profile"
  "${runner[@]}" "$bin" --label "$(label_of "$target")" "$@" >"$out.txt" 2>"$out.err" || status=$?
  grep -v '^#' "$out.txt" >>"$ROWS" || true
  if ((status != 0)); then
    FAILED_RUNS+=("$(label_of "$target") $profile (exit $status)")
    sed 's/^/    /' "$out.txt" "$out.err"
  fi
}

install_tools

log "build"
for profile in "${PROFILES[@]}"; do
  for target in "$HOST" native-cpu "${CROSS_TARGETS[@]}"; do
    build "$target" "$profile"
  done
done
pick_i686_runner

log "run"
# Files cross architectures: x86_64 writes, s390x verifies and writes, every
# other run verifies both.
run "$HOST" release --write "$FILES_X86"
run s390x-unknown-linux-gnu release --verify "$FILES_X86" --write "$FILES_S390X"
[[ -f $FILES_X86/WRITER && -f $FILES_S390X/WRITER ]] ||
  die "the x86_64 or s390x run wrote no snapshot/replay files"
BOTH=(--verify "$FILES_X86" --verify "$FILES_S390X")
run "$HOST" debug "${BOTH[@]}"
for profile in "${PROFILES[@]}"; do
  run native-cpu "$profile" "${BOTH[@]}"
  for target in "${CROSS_TARGETS[@]}"; do
    [[ $target == s390x-unknown-linux-gnu && $profile == release ]] && continue
    run "$target" "$profile" "${BOTH[@]}"
  done
done

echo
echo "== determinism table (target x profile x scene)"
printf '%-32s %-8s %-44s %-9s %s\n' target profile scene result detail
sort -s -k1,1 "$ROWS" | sed 's/  *$//'
total=$(grep -c . "$ROWS" || true)
bad=$(grep -c ' MISMATCH ' "$ROWS" || true)
ok=$((total - bad))
echo
echo "cross-determinism: $ok passed, $bad failed"
echo "cross-determinism: took ${SECONDS}s"
if ((bad > 0 || ${#FAILED_RUNS[@]} > 0)); then
  for f in "${FAILED_RUNS[@]}"; do echo "cross-determinism: failed run: $f" >&2; done
  echo "cross-determinism: MISMATCH. A golden hash that moves on one target or profile only is a" >&2
  echo "determinism bug. For an intended behaviour change: cargo run --release -p" >&2
  echo "clockwork2d-determinism --example determinism_suite -- --update-golden, then name" >&2
  echo "the change in CHANGELOG.md." >&2
  exit 1
fi
