#!/usr/bin/env bash
# The browser test of the web playground (web/test/browser.mjs) in Debian's
# Chromium, headless. Installs what it lacks: the chromium package and the
# pinned playwright-core (npm ci, from package-lock.json). Run after
# `bash web/build.sh` (which also builds the native CLI the test asks for
# native hashes and speeds).
set -euo pipefail
cd "$(dirname "$0")"
SECONDS=0
if [[ ! -x /usr/bin/chromium ]]; then
  sudo=()
  [[ $(id -u) == 0 ]] || sudo=(sudo)
  echo "== web test: apt-get install chromium"
  "${sudo[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get install -y -qq --no-install-recommends chromium >/dev/null
fi
/usr/bin/chromium --version
if [[ ! -d node_modules/playwright-core ]]; then
  echo "== web test: npm ci"
  npm ci --no-audit --no-fund
fi
echo "== web test: headless Chromium ($SECONDS s of installs)"
node browser.mjs
