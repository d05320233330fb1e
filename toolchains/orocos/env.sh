# shellcheck shell=bash
# Source this (bash): the Orocos toolchain 2.10 that build.sh beside this file installs into
# $OROCOS_HOME/install (default ~/orocos/install; OROCOS_INSTALL overrides the install folder), and the
# helper functions robomda's orocos_toolchain tests use:
#
#   oro_build_pkg PKGDIR          configure + build + install an Orocos CMake package (prefix PKGDIR/install)
#   oro_add_prefix DIR            make components / typekits / plugins installed under DIR findable
#   oro_verdict CMD ARGS...       run CMD; fail on a non-zero exit OR an RTT ERROR/FATAL/CRITICAL line
#                                 in its output or in $ORO_LOGFILE
#   oro_deploy_check FILE         deployer --check -s FILE (XML: load, connect, configure, no start)
#   oro_deploy_verify FILE SECS   deploy FILE (xml/cpf/ops/lua), run SECS seconds, then check every loaded
#                                 component is Running and has no property its C++ class does not declare;
#                                 shut down with SIGINT and require a clean exit
#   oro_rttlua_safe FILE          rttlua FILE non-interactively, with a timeout
#
# Tunables (environment): ORO_JOBS (make -j, default 2), ORO_CMAKE_ARGS (extra cmake args),
# ORO_TIMEOUT (seconds a deployer/rttlua run may take beyond SECS, default 120), ORO_KEEP (keep temp files).

OROCOS_INSTALL=${OROCOS_INSTALL:-${OROCOS_HOME:-$HOME/orocos}/install}
export OROCOS_INSTALL
export OROCOS_TARGET=gnulinux

_oro_prepend() {  # _oro_prepend VAR DIR: put DIR first in the :-separated VAR, once
  local var=$1 dir=$2 cur
  cur=${!var:-}
  case ":$cur:" in
    *":$dir:"*) cur=$(printf '%s' ":$cur:" | sed "s#:$dir:#:#g; s#^:##; s#:\$##") ;;
  esac
  export "$var=$dir${cur:+:$cur}"
}

_oro_prepend PATH "$OROCOS_INSTALL/bin"
_oro_prepend LD_LIBRARY_PATH "$OROCOS_INSTALL/lib"
_oro_prepend PKG_CONFIG_PATH "$OROCOS_INSTALL/lib/pkgconfig"
_oro_prepend CMAKE_PREFIX_PATH "$OROCOS_INSTALL"
# The deployer searches RTT_COMPONENT_PATH for component packages, typekits and plugins
# (<dir>/<pkg> and <dir>/gnulinux/<pkg>). Without the toolchain's own lib/orocos in it the
# RTT typekit and the OCL plugins are not found.
_oro_prepend RTT_COMPONENT_PATH "$OROCOS_INSTALL/lib/orocos"
case ";${LUA_PATH:-};" in
  *";$OROCOS_INSTALL/share/lua/5.1/?.lua;"*) ;;
  *) export LUA_PATH="$OROCOS_INSTALL/share/lua/5.1/?.lua;${LUA_PATH:-;}" ;;
esac
case ";${LUA_CPATH:-};" in
  *";$OROCOS_INSTALL/lib/lua/5.1/?.so;"*) ;;
  *) export LUA_CPATH="$OROCOS_INSTALL/lib/lua/5.1/?.so;${LUA_CPATH:-;}" ;;
esac

# RTT log lines at level Error or worse: "[ ERROR  ]", "[ FATAL  ]", "[CRITICAL]"; plus any
# stand-alone upper-case ERROR word (OCL/Lua helpers print "ERROR: ...").
ORO_ERROR_RE='\[ *(ERROR|FATAL|CRITICAL) *\]|(^|[^A-Za-z0-9_])ERROR([^A-Za-z0-9_]|$)'

oro_build_pkg() {
  local pkg
  pkg=$(readlink -f "${1:?usage: oro_build_pkg PKGDIR}") || return 2
  [ -f "$pkg/CMakeLists.txt" ] || { echo "oro_build_pkg: no CMakeLists.txt in $pkg" >&2; return 2; }
  local b=$pkg/build
  echo "oro_build_pkg: configure $pkg (prefix $pkg/install)"
  cmake -S "$pkg" -B "$b" -DCMAKE_INSTALL_PREFIX="$pkg/install" \
        -DCMAKE_PREFIX_PATH="$CMAKE_PREFIX_PATH" -DOROCOS_TARGET="$OROCOS_TARGET" \
        ${ORO_CMAKE_ARGS:-} || { echo "oro_build_pkg: cmake configure FAILED" >&2; return 1; }
  echo "oro_build_pkg: build"
  nice cmake --build "$b" -j "${ORO_JOBS:-2}" || { echo "oro_build_pkg: build FAILED" >&2; return 1; }
  echo "oro_build_pkg: install"
  cmake --build "$b" --target install || { echo "oro_build_pkg: make install FAILED" >&2; return 1; }
  # a package that installs no component library is not an Orocos component package
  if ! find "$pkg/install/lib/orocos" -name '*.so' 2>/dev/null | grep -q .; then
    echo "oro_build_pkg: nothing installed under $pkg/install/lib/orocos" >&2; return 1
  fi
  return 0
}

oro_add_prefix() {
  local d
  d=$(readlink -f "${1:?usage: oro_add_prefix DIR}") || return 2
  _oro_prepend RTT_COMPONENT_PATH "$d/lib/orocos"
  _oro_prepend LD_LIBRARY_PATH "$d/lib"
  _oro_prepend PKG_CONFIG_PATH "$d/lib/pkgconfig"
  _oro_prepend CMAKE_PREFIX_PATH "$d"
  [ -d "$d/bin" ] && _oro_prepend PATH "$d/bin"
  return 0
}

oro_verdict() {
  [ $# -gt 0 ] || { echo "usage: oro_verdict CMD ARGS..." >&2; return 2; }
  local log=${ORO_LOGFILE:-$PWD/orocos.log}
  case $log in /*) ;; *) log=$PWD/$log ;; esac
  export ORO_LOGFILE=$log
  : > "$log" 2>/dev/null  # this command's log only (RTT truncates it at start-up anyway)
  local out rc bad
  out=$(mktemp /tmp/oro_verdict.XXXXXX)
  "$@" </dev/null 2>&1 | tee "$out"
  rc=${PIPESTATUS[0]}
  bad=$( { grep -a -E "$ORO_ERROR_RE" "$out" | sed 's/^/output: /'
           [ -f "$log" ] && grep -a -E "$ORO_ERROR_RE" "$log" | sed "s#^#$log: #"; } | head -20)
  rm -f "$out"
  if [ "$rc" -ne 0 ]; then
    echo "oro_verdict: FAILED: '$*' exited $rc"
    [ -n "$bad" ] && printf '%s\n' "$bad"
    return 1
  fi
  if [ -n "$bad" ]; then
    echo "oro_verdict: FAILED: '$*' logged errors:"
    printf '%s\n' "$bad"
    return 1
  fi
  echo "oro_verdict: OK: '$*'"
  return 0
}

# The deployer and rttlua run in the directory of the deployment file (the generated files say
# "Run: deployer -s headlamp.xml"), not in the caller's: RTT's import("pkg") takes a directory named
# pkg in the current directory *instead of* RTT_COMPONENT_PATH (ComponentLoader::importInstalledPackage),
# so running from the parent of an output folder named like the package fails to find the components.
# ORO_RUN_IN_CWD=1 keeps the caller's directory.
_oro_rundir() { if [ -n "${ORO_RUN_IN_CWD:-}" ]; then pwd; else dirname "$1"; fi; }

oro_deploy_check() {
  local f
  f=$(readlink -f "${1:?usage: oro_deploy_check FILE}") || return 2
  [ -f "$f" ] || { echo "oro_deploy_check: no file $1" >&2; return 2; }
  # XML/cpf: --check loads, connects and configures, never starts, and exits (0 / 255).
  # .ops/.lua: the deployer has no check mode for scripts: --check runs the script as written and
  # exits without waiting (components are then stopped, cleaned up and unloaded).
  ( cd "$(_oro_rundir "$f")" && exec timeout -k 10 -s INT "${ORO_TIMEOUT:-120}" deployer --check -s "$f" </dev/null )
}

# _oro_instances FILE: "instance<TAB>type" for each component FILE loads
_oro_instances() {
  python3 - "$1" <<'PY'
import re, sys
import xml.etree.ElementTree as ET
f = sys.argv[1]
text = open(f, encoding="utf-8", errors="replace").read()
if f.endswith((".xml", ".cpf")):
    special = {"Import", "LoadLibrary", "Path", "Include"}
    root = ET.fromstring(re.sub(r"<!DOCTYPE[^>]*>", "", text).encode())
    for s in root.findall("struct"):
        t = s.get("type", "")
        if t not in ("ConnPolicy", "PropertyBag") and s.get("name") not in special:
            print(s.get("name") + "\t" + t)
else:
    # .ops: loadComponent("name", "Type")   .lua: depl:loadComponent("name", "Type")
    body = re.sub(r"(?m)^\s*(//|--).*$", "", text)
    for m in re.finditer(r'loadComponent\(\s*"([^"]+)"\s*,\s*"([^"]+)"', body):
        print(m.group(1) + "\t" + m.group(2))
PY
}

# _oro_verify_lua FILE SECS INSTANCES_TSV OUT.lua [wrap]: writes the verification script
_oro_verify_lua() {
  local file=$1 secs=$2 tsv=$3 out=$4 wrap=${5:-}
  {
    echo 'require("rttlib")'
    echo 'rttlib.color = false'
    echo "local SECS = $secs"
    echo "local FILE = [[$file]]"
    echo "local DONE = [[${out%.lua}.done]]"
    echo 'local expected = {'
    while IFS=$'\t' read -r n t; do [ -n "$n" ] && echo "  {[[$n]], [[$t]]},"; done < "$tsv"
    echo '}'
    cat <<'LUA'
local ok = true
local function done(tag)
  -- stdout of the deployer is a file (fully buffered): tell the caller through a file
  print(tag .. (ok and "OK" or "FAILED")); io.stdout:flush()
  local f = io.open(DONE, "w"); if f then f:write(ok and "OK\n" or "FAILED\n"); f:close() end
end
local function fail(m)
  rtt.logl("Error", "VERIFY FAILED: " .. m)
  print("VERIFY FAILED: " .. m)
  ok = false
end
local function deployer()
  local tc = rtt.getTC()
  if tc:getName() == "Deployer" then return tc end
  return tc:getPeer("Deployer")
end
local function deploy()
  -- exactly what `deployer -s FILE` does: kickStart for XML, runScript for scripts
  local depl = deployer()
  local r
  if FILE:match("%.xml$") or FILE:match("%.cpf$") then r = depl:kickStart(FILE)
  else r = depl:runScript(FILE) end
  if not r then fail("the deployer failed on " .. FILE .. " (kickStart/runScript returned false)") end
end
local function verify()
  local depl = deployer()
  rtt.sleep(SECS, 0)
  local peers = depl:getPeers()
  local isPeer, typeOf = {}, {}
  for _, p in ipairs(peers) do isPeer[p] = true end
  for _, e in ipairs(expected) do
    typeOf[e[1]] = e[2]
    if not isPeer[e[1]] then fail("component '" .. e[1] .. "' (" .. e[2] .. ") is not loaded") end
  end
  if #peers == 0 then fail("no component loaded") end
  for _, p in ipairs(peers) do
    local s = depl:getPeer(p):getState()
    print("VERIFY: " .. p .. " is " .. tostring(s))
    if s ~= "Running" then fail("component '" .. p .. "' is " .. tostring(s) .. ", not Running") end
  end
  -- properties: compare with a fresh instance of the same C++ type (the deployer silently
  -- adds a new property for every unknown name under Properties)
  for _, p in ipairs(peers) do
    local t = typeOf[p]
    if not t then
      fail("cannot tell the type of '" .. p .. "' from " .. FILE .. ": property check impossible")
    else
      local probe = "oro_verify_probe__" .. p
      if not depl:loadComponent(probe, t) then
        fail("cannot instantiate " .. t .. " to check the properties of '" .. p .. "'")
      else
        local decl = {}
        for _, n in ipairs(depl:getPeer(probe):getPropertyNames()) do decl[n] = true end
        for _, n in ipairs(depl:getPeer(p):getPropertyNames()) do
          if not decl[n] then
            fail("component '" .. p .. "' has property '" .. n .. "' that " .. t .. " does not declare")
          end
        end
        depl:unloadComponent(probe)
      end
    end
  end
  print("VERIFY-RESULT: " .. (ok and "OK" or "FAILED"))
end
LUA
    if [ -n "$wrap" ]; then
      # FILE is itself a Lua deployment: run it here; verify while it sleeps (its components run),
      # or after it returns; its os.exit() is deferred until the verification is done.
      cat <<'LUA'
local verified = false
local real_sleep, real_exit = rtt.sleep, os.exit
local exit_code = nil
rtt.sleep = function(s, ns) real_sleep(s, ns); if not verified then verified = true; verify() end end
os.exit = function(c)
  if c == nil or c == true then exit_code = 0 elseif c == false then exit_code = 1 else exit_code = c end
  error("__oro_script_exit__", 0)
end
local okcall, err = pcall(dofile, FILE)
rtt.sleep, os.exit = real_sleep, real_exit
if not okcall and err ~= "__oro_script_exit__" then fail("script error: " .. tostring(err)) end
if not verified then verified = true; verify() end
if exit_code ~= nil and exit_code ~= 0 then fail("the script exited with " .. tostring(exit_code)) end
done("VERIFY-DONE: ")
LUA
    else
      echo 'deploy()'
      echo 'verify()'
      echo 'done("VERIFY-DONE: ")'
    fi
  } > "$out"
}

oro_deploy_verify() {
  local f secs
  f=$(readlink -f "${1:?usage: oro_deploy_verify FILE SECONDS}") || return 2
  secs=${2:-2}
  [ -f "$f" ] || { echo "oro_deploy_verify: no file $1" >&2; return 2; }
  local tmp; tmp=$(mktemp -d /tmp/oro_verify.XXXXXX)
  _oro_instances "$f" > "$tmp/instances.tsv" || { echo "oro_deploy_verify: cannot parse $f"; return 2; }
  echo "oro_deploy_verify: $f loads: $(cut -f1 "$tmp/instances.tsv" | tr '\n' ' ')"
  local args
  case "$f" in
    *.lua) _oro_verify_lua "$f" "$secs" "$tmp/instances.tsv" "$tmp/verify.lua" wrap
           args=(-s "$tmp/verify.lua") ;;
    *.xml|*.cpf|*.ops|*.osd)
           _oro_verify_lua "$f" "$secs" "$tmp/instances.tsv" "$tmp/verify.lua"
           args=(-s "$tmp/verify.lua") ;;
    *) echo "oro_deploy_verify: unknown extension: $f"; return 2 ;;
  esac
  # verify.lua deploys FILE the way `deployer -s FILE` does (DeploymentComponent::kickStart for XML,
  # ::runScript for .ops), waits SECS, checks, prints VERIFY-DONE. The deployer then (stdin not a
  # terminal) waits for SIGINT/SIGTERM/SIGHUP and shuts the deployment down.
  ( cd "$(_oro_rundir "$f")" && exec deployer "${args[@]}" </dev/null > "$tmp/out" 2>&1 ) &
  local pid=$! waited=0 limit=$((secs + ${ORO_TIMEOUT:-120})) rc
  while kill -0 $pid 2>/dev/null && [ ! -f "$tmp/verify.done" ] && [ $waited -lt $limit ]; do
    sleep 1; waited=$((waited + 1))
  done
  local exited_early=0 timed_out=0
  if kill -0 $pid 2>/dev/null; then
    [ -f "$tmp/verify.done" ] || timed_out=1
    sleep 1   # let the deployer reach its signal wait
    kill -INT $pid 2>/dev/null
    local w=0
    while kill -0 $pid 2>/dev/null && [ $w -lt 30 ]; do sleep 1; w=$((w + 1)); done
    if kill -0 $pid 2>/dev/null; then
      echo "oro_deploy_verify: deployer did not shut down within 30 s of SIGINT: killed" >> "$tmp/out"
      kill -KILL $pid 2>/dev/null
    fi
  else
    exited_early=1
  fi
  wait $pid; rc=$?
  cat "$tmp/out"
  local verdict=0
  if [ $timed_out = 1 ]; then echo "oro_deploy_verify: FAILED: no verification result within $limit s"; verdict=1; fi
  if [ $exited_early = 1 ] && [ ! -f "$tmp/verify.done" ]; then
    echo "oro_deploy_verify: FAILED: the deployer exited (status $rc) before the verification ran"; verdict=1
  fi
  if [ $rc -ne 0 ]; then echo "oro_deploy_verify: FAILED: deployer exit status $rc"; verdict=1; fi
  if [ "$(cat "$tmp/verify.done" 2>/dev/null)" != OK ]; then
    [ $verdict = 0 ] && echo "oro_deploy_verify: FAILED: verification failed"; verdict=1
  fi
  [ -n "${ORO_KEEP:-}" ] && echo "oro_deploy_verify: temp files in $tmp" || rm -rf "$tmp"
  [ $verdict = 0 ] && echo "oro_deploy_verify: OK: every component Running for ${secs}s, declared properties only, clean shutdown"
  return $verdict
}

oro_rttlua_safe() {
  local f
  f=$(readlink -f "${1:?usage: oro_rttlua_safe FILE}") || return 2
  [ -f "$f" ] || { echo "oro_rttlua_safe: no file $1" >&2; return 2; }
  # rttlua runs FILE and exits (exit status 0 unless the script calls os.exit); stdin is not a
  # terminal, and a script that waits forever is interrupted.
  ( cd "$(_oro_rundir "$f")" && exec timeout -k 10 -s INT "${ORO_TIMEOUT:-120}" rttlua "$f" </dev/null )
}
