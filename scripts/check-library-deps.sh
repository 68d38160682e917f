#!/usr/bin/env bash
# The library a game depends on (the root package, clockwork2d) has exactly
# three normal dependencies: fixed, serde and bincode (ARCHITECTURE.md,
# "Workspace"). Everything a tool needs lives in a member crate. Optional
# dependencies count too: a feature must not pull a tool into the library.
#
# Reads `cargo metadata` (no network needed once the lock file is resolved)
# and exits 1 naming any extra or missing dependency.
set -euo pipefail
cd "$(dirname "$0")/.."
cargo metadata --format-version 1 --no-deps | python3 -c '
import json, sys
expected = {"fixed", "serde", "bincode"}
meta = json.load(sys.stdin)
lib = next(p for p in meta["packages"] if p["name"] == "clockwork2d")
normal = {d["name"] for d in lib["dependencies"] if d["kind"] is None}
extra, missing = sorted(normal - expected), sorted(expected - normal)
if extra or missing:
    print(f"check-library-deps: the library must depend on exactly {sorted(expected)}; "
          f"extra: {extra}, missing: {missing}. Move tool dependencies to a member crate.",
          file=sys.stderr)
    sys.exit(1)
print(f"check-library-deps: ok (normal dependencies: {sorted(normal)})")
'
