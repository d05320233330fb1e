# Shared by toolchains/*/build.sh (sourced, not run): the reporting helpers and the Debian step.
# The caller sets APT_PACKAGES (array), CHECK (1: --check, install nothing) and APT (0: --no-apt).

MISSING=0
say() { printf 'build.sh: %s\n' "$*"; }
missing() { say "MISSING: $*"; MISSING=1; }

# the packages of APT_PACKAGES that dpkg does not have installed, one a line
apt_missing() {
  local p
  for p in "${APT_PACKAGES[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' || echo "$p"
  done
}

# install what APT_PACKAGES lacks (with sudo when not root), or, under --check / --no-apt, name it
apt_step() {
  local absent
  mapfile -t absent < <(apt_missing)
  if [ ${#absent[@]} -eq 0 ]; then
    say "Debian packages: all ${#APT_PACKAGES[@]} installed"
  elif [ "$CHECK" = 1 ] || [ "$APT" = 0 ]; then
    missing "Debian packages ${absent[*]} (apt-get install them)"
  else
    local sudo=(); [ "$(id -u)" = 0 ] || sudo=(sudo)
    say "installing Debian packages: ${absent[*]}"
    "${sudo[@]}" apt-get update -q
    DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get install -y -q --no-install-recommends "${absent[@]}"
  fi
}
