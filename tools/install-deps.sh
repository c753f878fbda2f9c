#!/usr/bin/env bash
# Installs the Debian/Ubuntu packages this project needs, if any are missing, plus any package
# names given as arguments (CI adds clang). Works as root or through sudo; does nothing when
# everything is already there.
set -euo pipefail

packages=(cmake make g++ pkg-config catch2 libstb-dev bubblewrap procps zip unzip python3 git libtinyobjloader-dev
          libgif-dev libglm-dev nlohmann-json3-dev
          libsdl2-dev xvfb xauth  # the viewer (tools/viewer) and its test under a virtual X server
          "$@")
# Optional: used by tests that look at pages (headless Chromium); installed where the
# distribution has them as a real package, and the tests that need them skip otherwise.
optional=(chromium)

installed() { [ "$(dpkg-query -W -f='${Status}' "$1" 2>/dev/null)" = "install ok installed" ]; }
# The policy is read whole before it is searched: `grep -q` in a pipe would stop reading at the
# first match, apt-cache would die of SIGPIPE, and pipefail would count that as "no candidate".
has_candidate() {
  local policy
  policy=$(apt-cache policy "$1" 2>/dev/null) || return 1
  grep -q 'Candidate: [0-9]' <<<"$policy"
}

# clang comes with its libFuzzer runtime (tools/fuzz.sh, `make fuzz`): libclang-rt-dev on
# Debian 12; Ubuntu 22.04 ships it inside clang's own libclang-common package.
for p in "$@"; do
  if [ "$p" = clang ] && grep -qs '^ID=debian' /etc/os-release; then
    packages+=(libclang-rt-dev)
  fi
done

missing=()
for p in "${packages[@]}"; do
  installed "$p" || missing+=("$p")
done
missing_optional=()
for p in "${optional[@]}"; do
  installed "$p" || missing_optional+=("$p")
done
if [ ${#missing[@]} -eq 0 ] && [ ${#missing_optional[@]} -eq 0 ]; then
  exit 0
fi

if [ "$(id -u)" -eq 0 ]; then
  sudo=()
elif command -v sudo >/dev/null 2>&1; then
  sudo=(sudo)
elif [ ${#missing[@]} -eq 0 ]; then
  exit 0  # only optional packages are missing, and nothing can install them
else
  echo "error: need root or sudo to install: ${missing[*]}" >&2
  exit 1
fi
export DEBIAN_FRONTEND=noninteractive
if [ ${#missing[@]} -gt 0 ]; then
  echo "Installing: ${missing[*]}"
  "${sudo[@]}" apt-get update -qq
  # A package the distribution does not offer would make apt-get fail with a bare "Unable to
  # locate package": say which, and on Ubuntu where they live (the universe component, which a
  # desktop install enables and a minimal system may not).
  unknown=()
  for p in "${missing[@]}"; do has_candidate "$p" || unknown+=("$p"); done
  if [ ${#unknown[@]} -gt 0 ]; then
    echo "error: this system's package sources offer no ${unknown[*]}" >&2
    if grep -qs '^ID=ubuntu' /etc/os-release; then
      echo "On Ubuntu they are in the 'universe' component: sudo add-apt-repository universe (package software-properties-common), then run this again." >&2
    fi
    exit 1
  fi
  "${sudo[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
if [ ${#missing[@]} -eq 0 ] && [ ${#missing_optional[@]} -gt 0 ]; then
  "${sudo[@]}" apt-get update -qq  # the package lists may be older than the distribution's
fi
for p in "${missing_optional[@]}"; do
  if has_candidate "$p"; then
    echo "Installing (optional): $p"
    "${sudo[@]}" apt-get install -y -qq --no-install-recommends "$p" >/dev/null ||
      echo "note: $p could not be installed; the tests that need it will be skipped"
  fi
done
