# Shared by toolchains/*/build.sh (sourced, not run): the reporting helpers, the common options, the
# Debian step and the sources at their verified commits. The caller sets APT_PACKAGES (array), CHECK
# (1: --check, install nothing) and APT (0: --no-apt), or lets parse_options set them.

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
    # wait for another apt (an unattended upgrade, a second build) instead of failing, as tests/run.sh does
    "${sudo[@]}" apt-get -o DPkg::Lock::Timeout=600 update -q
    DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get -o DPkg::Lock::Timeout=600 install -y -q --no-install-recommends "${absent[@]}"
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

# parse_options ARGS...: --check, --no-apt, --sources-only, --help (the script's header) into CHECK,
# APT and SOURCES_ONLY; anything else is a usage error
parse_options() {
  CHECK=0 APT=1 SOURCES_ONLY=0
  local arg
  for arg in "$@"; do
    case $arg in
      --check) CHECK=1 ;;
      --no-apt) APT=0 ;;
      --sources-only) SOURCES_ONLY=1 ;;
      -h|--help) sed -n '2,/^set -euo/p' "$0" | sed '$d; s/^# \{0,1\}//'; exit 0 ;;
      *) echo "$(basename "$0"): unknown option $arg (see --help)" >&2; exit 2 ;;
    esac
  done
}

# fetch_sources TSV OWNER: each line of TSV (name, url, ref, commit) cloned into $SRC/name, from
# $MIRROR/OWNER+name/repo when that exists (fetched bare mirrors), else from the url, then its verified
# commit checked out; an existing clone is only compared with it under --check. With --sources-only
# (and no --check) the script ends there.
fetch_sources() {
  local tsv=$1 owner=$2 name url ref commit dest got from
  while IFS=$'\t' read -r name url ref commit; do
    case $name in ''|'#'*) continue ;; esac
    dest=$SRC/$name
    if [ -d "$dest/.git" ]; then
      got=$(git -C "$dest" rev-parse HEAD)
      if [ "$got" = "$commit" ]; then say "source $name: at the verified $commit"
      elif [ "$CHECK" = 1 ]; then say "source $name: at $got, not the verified $commit"
      else git -C "$dest" -c advice.detachedHead=false checkout -q "$commit"; say "source $name: checked out $commit"; fi
      continue
    fi
    if [ "$CHECK" = 1 ]; then missing "source $name ($url $ref) in $SRC"; continue; fi
    mkdir -p "$SRC"
    from=$url
    if [ -n "${MIRROR:-}" ] && [ -d "$MIRROR/$owner+$name/repo" ]; then from=$MIRROR/$owner+$name/repo; fi
    say "source $name: git clone --branch $ref $from"
    git clone -q --branch "$ref" "$from" "$dest"
    git -C "$dest" -c advice.detachedHead=false checkout -q "$commit"
  done < "$tsv"
  if [ "$SOURCES_ONLY" = 1 ] && [ "$CHECK" = 0 ]; then say "sources fetched into $SRC"; exit 0; fi
}
