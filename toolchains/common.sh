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

# _run LABEL EXPECTED CMD...: run CMD (RUN_TIMEOUT s, default 60, at most; stdin closed); it must exit 0
# and print EXPECTED, else it is missing (the --check of a tree that cannot run)
_run() {
  local label=$1 expected=$2 out rc=0
  shift 2
  out=$(timeout -k 5 "${RUN_TIMEOUT:-60}" "$@" </dev/null 2>&1) || rc=$?
  if [ $rc = 0 ] && grep -q -- "$expected" <<<"$out"; then say "run: $label: OK"
  else missing "run: $label failed (exit $rc): $(tail -n 5 <<<"$out" | tr '\n' ' ')"; fi
}
