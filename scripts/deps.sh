#!/usr/bin/env bash
# Installs the Debian packages taut needs, only those missing. Idempotent and quiet when
# nothing is missing. Used by `make run` and `make test`.
set -euo pipefail
pkgs=(cmake make g++ pkg-config
      libboost-dev libboost-graph-dev libcgal-dev libgmp-dev libmpfr-dev
      libxml2-dev libxml2-utils nlohmann-json3-dev libcli11-dev
      libgtest-dev libgmock-dev libbenchmark-dev gzip)
missing=()
for p in "${pkgs[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0
echo "deps: installing ${missing[*]}" >&2
sudo=""
[ "$(id -u)" -eq 0 ] || sudo="sudo"
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq >/dev/null
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
