# Sourced by setup.sh and setup_cuda.sh: fetches Kokkos 3.4.01 from Debian
# and builds it.
# Debian ships it inside the trilinos source package. It is fetched with a
# private apt configuration, so the machine's own apt setup stays untouched:
# the machine's own package sources (a mirror or proxy included), turned into
# source-package entries. The tarball is kept in $cache/dl for the next build.
#   kokkos_source WORK   extracts into WORK/src and prints the Kokkos folder
kokkos_source() {
  local work=$1 dl="$cache/dl"
  mkdir -p "$work/lists/partial" "$work/sources.list.d" "$dl"
  if ! ls "$dl"/trilinos_*.orig.tar.* >/dev/null 2>&1; then
    local apt_etc f
    apt_etc=$(apt-config shell E Dir::Etc/d | sed -n "s/^E='\(.*\)'$/\1/p"); apt_etc=${apt_etc:-/etc/apt/}
    touch "$work/sources.list"
    [[ -f "$apt_etc/sources.list" ]] && sed -n 's/^[[:space:]]*deb[[:space:]]/deb-src /p' "$apt_etc/sources.list" >"$work/sources.list"
    for f in "$apt_etc"/sources.list.d/*.list; do
      [[ -f "$f" ]] && sed -n 's/^[[:space:]]*deb[[:space:]]/deb-src /p' "$f" >"$work/sources.list.d/$(basename "$f")"
    done
    for f in "$apt_etc"/sources.list.d/*.sources; do
      [[ -f "$f" ]] && sed 's/^Types:.*/Types: deb-src/' "$f" >"$work/sources.list.d/$(basename "$f")"
    done
    local apt_opts=(-o Dir::Etc::SourceList="$work/sources.list" -o Dir::Etc::SourceParts="$work/sources.list.d"
                    -o Dir::State::Lists="$work/lists" -o Debug::NoDropPrivs=true -o APT::Sandbox::User=root)
    # An index that fails to download (a source with no source packages) is not
    # fatal here: the download of trilinos below says whether one source had it.
    { apt-get "${apt_opts[@]}" update -q || true
      (cd "$dl" && apt-get "${apt_opts[@]}" source --download-only trilinos); } >"$work/fetch.log" 2>&1 ||
      { cat "$work/fetch.log" >&2; say "could not fetch Debian's trilinos source package from this machine's apt sources"; return 1; }
  fi
  local tarball
  tarball=$(ls "$dl"/trilinos_*.orig.tar.* | head -n1)
  say "extracting packages/kokkos from $(basename "$tarball")"
  mkdir -p "$work/src"
  tar -xf "$tarball" -C "$work/src" --wildcards '*/packages/kokkos/*' || return 1
  ls -d "$work"/src/*/packages/kokkos
}

#   kokkos_build SRC WORK PREFIX LOG [CMAKE ARGS...]   configures, builds and
#   installs the Kokkos in SRC into PREFIX (a Release build, C++17), marks it
#   complete and removes WORK; on failure shows the log's end and returns 1.
kokkos_build() {
  local src=$1 work=$2 prefix=$3 log=$4; shift 4
  local generator=()
  command -v ninja >/dev/null && generator=(-G Ninja)
  {
    cmake -S "$src" -B "$work/build" "${generator[@]}" -DCMAKE_BUILD_TYPE=Release \
      -DCMAKE_INSTALL_PREFIX="$prefix" -DCMAKE_CXX_STANDARD=17 "$@" &&
    cmake --build "$work/build" --parallel "$(nproc)" &&
    cmake --install "$work/build"
  } >"$log" 2>&1 || { tail -n 60 "$log" >&2; say "Kokkos build failed; full log: $log"; return 1; }
  touch "$prefix/.complete"
  rm -rf "$work"
}
