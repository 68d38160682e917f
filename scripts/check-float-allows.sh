#!/usr/bin/env bash
# No float arithmetic on the simulation path (ARCHITECTURE.md, "Determinism rules").
#
# The compiler enforces it: the library (src/lib.rs), the scene crate
# (scene/src/lib.rs, which builds worlds) and the determinism suite
# (determinism/src/lib.rs and its runner) have
# #![deny(clippy::float_arithmetic)], which covers every module, and CI runs
# clippy with -D warnings. This script checks that nobody switched the lint
# off:
#
#   * those crate roots still deny clippy::float_arithmetic crate-wide;
#   * Cargo.toml's lint table does not allow it;
#   * an allow/expect/warn of clippy::float_arithmetic (or of the whole
#     clippy::restriction group, or a cfg_attr that does either) appears in
#     those crates only
#       - in the reference f64/f32 scalar impls (ALLOWED below, with the
#         most allows each file may hold), or
#       - below a file's first #[cfg(test)] (unit tests computing reference
#         values in f64), or
#     (the CLI crate, cli/, is command-line edge code: reports, timings;
#     the render crate, render/, is drawing code: it reads a world's state,
#     converts it to f64/f32 and draws, and nothing it computes goes back
#     into a world; neither is checked);
#   * none of the checked crates depends on the render crate, so drawing
#     code (floats) cannot become part of what builds or steps a world (the
#     library itself may depend on fixed, serde and bincode only:
#     scripts/check-library-deps.sh).
#
# Exit 0 when clean; 1 with one line per offending allow otherwise.
set -euo pipefail
cd "$(dirname "$0")/.."

# path|most allows|why
ALLOWED=(
  "src/math/float_impls.rs|1|the f64/f32 reference Scalar impls (module-wide allow)"
  "src/math/wide.rs|1|the f64 wide type of the reference scalars (impl_wide_float)"
)

status=0
fail() {
  echo "check-float-allows: $*" >&2
  status=1
}

ROOTS=(src/lib.rs scene/src/lib.rs determinism/src/lib.rs determinism/examples/determinism_suite.rs)
for root in "${ROOTS[@]}"; do
  if ! grep -Eq '^#!\[deny\(clippy::float_arithmetic\)\]' "$root"; then
    fail "$root must keep #![deny(clippy::float_arithmetic)] (crate-wide)"
  fi
done
for manifest in Cargo.toml scene/Cargo.toml determinism/Cargo.toml; do
  if grep -Eq 'float_arithmetic[[:space:]]*=[[:space:]]*("(allow|warn)"|\{[^}]*level[[:space:]]*=[[:space:]]*"(allow|warn)")' "$manifest"; then
    fail "$manifest's lint table must not allow or weaken float_arithmetic"
  fi
done

for manifest in scene/Cargo.toml determinism/Cargo.toml; do
  if grep -q 'clockwork2d-render' "$manifest"; then
    fail "$manifest must not depend on clockwork2d-render (drawing code uses floats; it stays outside the simulation path)"
  fi
done

pattern='(allow|expect|warn)[[:space:]]*\([^)]*clippy::(float_arithmetic|restriction)'

budget_for() {
  local file=$1 entry
  for entry in "${ALLOWED[@]}"; do
    if [[ ${entry%%|*} == "$file" ]]; then
      entry=${entry#*|}
      echo "${entry%%|*}"
      return
    fi
  done
  echo 0
}

while IFS= read -r file; do
  # Allows above the first #[cfg(test)] line (non-test code), as "line:text".
  hits=$(awk -v pat="$pattern" '
    /^[[:space:]]*#\[cfg\(test\)\]/ { exit }
    $0 ~ pat { print FNR ":" $0 }
  ' "$file")
  [[ -z $hits ]] && continue
  count=$(printf '%s\n' "$hits" | wc -l)
  budget=$(budget_for "$file")
  if ((count > budget)); then
    while IFS= read -r hit; do
      fail "$file:${hit%%:*}: float arithmetic allowed outside the reference scalar impls and tests:${hit#*:}"
    done <<<"$hits"
  fi
done < <(grep -rlE "$pattern" src scene/src determinism/src determinism/examples --include='*.rs' || true)

if ((status == 0)); then
  echo "check-float-allows: ok (clippy::float_arithmetic denied crate-wide; allowed only in the reference scalar impls and unit tests; cli/ and render/ are edge code)"
else
  echo "check-float-allows: the simulation path must stay free of f32/f64 arithmetic (see ARCHITECTURE.md); convert at the edge with fx()/to_f64() instead" >&2
fi
exit "$status"
