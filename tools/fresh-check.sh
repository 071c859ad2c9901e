#!/usr/bin/env bash
# The fresh-machine check: `./lab fresh-check bookworm|trixie [--keep] [--only demo|test|web|ci] [--web]`.
#
# Builds a minimal Debian root with debootstrap (nothing in it but tools/base-packages.txt), clones
# the *committed* tree (HEAD) into it, and runs the README's two commands there as root, the way a
# student on a new machine would: `./lab demo`, then `./lab test`. Each command's exit status and
# wall time is printed as a table and appended to $WORK/results.tsv. With --web (or --only web) the
# browser path follows: `./lab test --web` (it installs Emscripten and chromium, builds the page with
# em++ and runs the browser tests), as a student who wants the app in a browser would.
# --only ci runs what CI runs on a new machine: `bash .ci/run` (`./lab test`, then `./lab test --web --quick`).
#
# The commands run in a chroot whose root is a mount point of its own (bubblewrap, the grader's
# sandbox, needs that: "Failed to make / slave" otherwise), with /proc, /sys and /dev from the host
# (bound with --rbind and made slaves, so unmounting them never unmounts the host's). Inside a
# chroot the kernel refuses new user namespaces, so the grader takes its root-mode path there.
#
# With --devcontainer the root starts as bare as the image the dev container builds on (debootstrap
# minbase, nothing included) and is then set up by the instructions of .devcontainer/Dockerfile (COPY,
# RUN, ENV) executed in order, as a container engine would; the two commands run after that, and the
# browser desktop (clothlab-desktop) must answer on port 6080. No container engine is needed.
#
# It needs root, debootstrap and a reachable Debian mirror (the one apt uses here, or
# CLOTHLAB_MIRROR). It takes 15-30 minutes per release on 2 cores: it is not part of ./lab test.
set -euo pipefail
ROOT=${CLOTHLAB_ROOT:-$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)}

die() { printf 'error: %s\n' "$*" >&2; exit 1; }
say() { printf '\033[1m==> %s\033[0m\n' "$*" >&2; }

release="" keep=0 only=(demo test) devcontainer=0 web=0
while (($#)); do
  case $1 in
    --keep) keep=1; shift ;;
    --devcontainer) devcontainer=1; shift ;;
    --only) [[ ${2:-} =~ ^(demo|test|web|ci)$ ]] || die "fresh-check: --only: demo, test, web or ci, not '${2:-}'"; only=("$2"); shift 2 ;;
    --web) web=1; shift ;;
    -*) die "fresh-check: unknown option $1 (usage: ./lab fresh-check bookworm|trixie [--keep] [--only demo|test|web|ci] [--web] [--devcontainer])" ;;
    *) [[ -z $release ]] || die "fresh-check: one release at a time"; release=$1; shift ;;
  esac
done
case $release in
  bookworm|trixie) ;;
  "") die "fresh-check: usage: ./lab fresh-check bookworm|trixie [--keep] [--only demo|test|web|ci] [--web] [--devcontainer]" ;;
  *) die "fresh-check: release '$release': bookworm (Debian 12) or trixie (Debian 13)" ;;
esac
[[ $(id -u) -eq 0 ]] || die "fresh-check: needs root (debootstrap, chroot and mounts)"
command -v debootstrap >/dev/null || die "fresh-check: debootstrap is not installed (apt-get install debootstrap)"
git -C "$ROOT" rev-parse --verify -q HEAD >/dev/null || die "$ROOT: (git): not a git checkout with a commit"

# The mirror: CLOTHLAB_MIRROR, else the first Debian archive apt uses on this machine.
mirror=${CLOTHLAB_MIRROR:-}
if [[ -z $mirror ]]; then
  mirror=$(cat /etc/apt/sources.list /etc/apt/sources.list.d/*.sources /etc/apt/sources.list.d/*.list 2>/dev/null \
           | grep -v '^\s*#' | grep -o -E 'https?://[^ ]*/debian/?' | grep -v -- '-security' | head -1 || true)
fi
[[ -n $mirror ]] || die "fresh-check: no Debian mirror found in /etc/apt; set CLOTHLAB_MIRROR"

mapfile -t base < <(grep -v -E '^\s*(#|$)' "$ROOT/tools/base-packages.txt")
work=${CLOTHLAB_FRESH_DIR:-/var/tmp/clothlab-fresh}
target=$work/$release
label=$release
if ((devcontainer)); then
  [[ $release == trixie ]] || die "fresh-check: --devcontainer: the dev container is Debian 13 (trixie)"
  base=()  # the image's own packages only: the Dockerfile installs the rest
  target=$work/$release-devcontainer label="$release (dev container)"
fi
commit=$(git -C "$ROOT" rev-parse --short HEAD)
mkdir -p "$work"
# One check per root at a time: a second one would remove the first one's root while it runs.
exec 9>"$target.lock"
flock -n 9 || die "fresh-check: another fresh-check of $label is running (it holds $target.lock): wait for it to end"

mounts=()
cleanup() {
  local m i
  for ((i = ${#mounts[@]} - 1; i >= 0; i--)); do
    m=${mounts[i]}
    mountpoint -q "$m" && { umount -R "$m" 2>/dev/null || umount -l -R "$m" 2>/dev/null || true; }
  done
  mounts=()
  if ((keep == 0)) && [[ -d $target ]]; then rm -rf --one-file-system "$target"; fi
}
trap cleanup EXIT
trap 'exit 130' INT TERM

# A root left by an earlier run (--keep, or a run that was stopped) is not fresh: start over.
if [[ -d $target ]]; then
  while read -r m; do umount -R "$m" 2>/dev/null || umount -l "$m" 2>/dev/null || true; done \
    < <(awk -v t="$target" 'index($2, t) == 1 { print $2 }' /proc/mounts | sort -r)
  rm -rf --one-file-system "$target"
fi

include=(); ((${#base[@]})) && include=(--include="$(IFS=,; echo "${base[*]}")")
say "fresh-check $label: debootstrap --variant=minbase ${include[*]} from $mirror"
t0=$(date +%s)
debootstrap --variant=minbase "${include[@]}" "$release" "$target" "$mirror" \
  >"$work/$release.debootstrap.log" 2>&1 || { tail -20 "$work/$release.debootstrap.log" >&2; die "fresh-check: debootstrap failed (log: $work/$release.debootstrap.log)"; }
say "fresh-check $label: root made in $(($(date +%s) - t0)) s"

# The committed tree only: a clone of HEAD, as a student gets it.
git clone -q --no-local --no-hardlinks "$ROOT" "$target/root/clothlab"
git -C "$target/root/clothlab" checkout -q --detach "$(git -C "$ROOT" rev-parse HEAD)"
# shared/ (the project's steering notes) sits beside a CI clone; the tests do not need it.

# The root a mount point of its own; the host's /proc, /sys and /dev inside it.
mount --bind "$target" "$target"; mounts+=("$target")
mount -t proc proc "$target/proc"; mounts+=("$target/proc")
for d in sys dev; do
  mount --rbind "/$d" "$target/$d" && mount --make-rslave "$target/$d"; mounts+=("$target/$d")
done
cp -L /etc/resolv.conf "$target/etc/resolv.conf" 2>/dev/null || true

# dockerfile_steps: the Dockerfile's COPY, RUN and ENV instructions in order, in the root (its build
# context is the repository, as devcontainer.json says); continuation lines joined.
dockerfile_steps() {
  local df=$target/root/clothlab/.devcontainer/Dockerfile kw rest envs=() n=0
  while IFS= read -r line; do
    [[ $line =~ ^[[:space:]]*(#|$) ]] && continue
    kw=${line%% *} rest=${line#* }
    n=$((n + 1))
    case $kw in
      FROM) ;;
      COPY) read -r -a words <<<"$rest"
            mkdir -p "$target$(dirname "${words[1]}")"
            cp -a "$target/root/clothlab/${words[0]}" "$target${words[1]}" ;;
      ENV) envs+=("$rest") ;;
      RUN) say "Dockerfile: RUN $rest"
           chroot "$target" /usr/bin/env -i HOME=/root PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin \
             DEBIAN_FRONTEND=noninteractive "${envs[@]}" sh -c "$rest" >>"$work/$release.dockerfile.log" 2>&1 \
             || { tail -20 "$work/$release.dockerfile.log" >&2; die "fresh-check: .devcontainer/Dockerfile: RUN $rest: failed (log: $work/$release.dockerfile.log)"; } ;;
      *) die "fresh-check: .devcontainer/Dockerfile: $kw: an instruction this check does not run" ;;
    esac
  done < <(sed -e ':a' -e '/\\$/N; s/\\\n//; ta' "$df")
}

run_in_root() {  # run_in_root LOG COMMAND...: in the chroot, a clean environment like a login as root
  local log=$1; shift
  chroot "$target" /usr/bin/env -i HOME=/root PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin \
    LANG=C.UTF-8 TERM=dumb CI=true bash -c "cd /root/clothlab && $*" >"$log" 2>&1
}

if ((devcontainer)); then
  t0=$(date +%s)
  dockerfile_steps
  say "fresh-check $label: the Dockerfile's steps took $(($(date +%s) - t0)) s"
fi

((web)) && [[ " ${only[*]} " != *" web "* ]] && only+=(web)
results=()
pretty=$(awk -F= '$1 == "PRETTY_NAME" { gsub(/"/, "", $2); print $2 }' "$target/etc/os-release")
for c in "${only[@]}"; do
  log=$work/${target##*/}.$c.log
  command="./lab $c"
  [[ $c == web ]] && command="./lab test --web"  # the browser tests (label web)
  [[ $c == ci ]] && command="bash .ci/run"       # what CI runs: ./lab test, then ./lab test --web --quick
  say "fresh-check $release: $command (log: $log)"
  t0=$(date +%s)
  status=0
  run_in_root "$log" "$command" || status=$?
  secs=$(($(date +%s) - t0))
  verdict=passed; ((status == 0)) || verdict=failed
  tail_line=$(grep -E 'tests passed|tests failed' "$log" | tail -1 || true)
  results+=("$label	$pretty	$command	$secs	$status	$verdict	${tail_line:-}")
  printf '%s\t%s\t./lab %s\t%s\t%s\t%s\t%s\t%s\n' "$(date -u +%F)" "$label" "${command#./lab }" "$secs" "$status" "$verdict" "$commit" "${tail_line:-}" >>"$work/results.tsv"
  ((status == 0)) || tail -30 "$log" >&2
done

if ((devcontainer)); then  # the browser desktop answers on port 6080
  chroot "$target" /usr/bin/env -i PATH=/usr/local/bin:/usr/bin:/bin HOME=/root clothlab-desktop >"$work/$release.desktop.log" 2>&1 || true
  status=1
  for _ in $(seq 30); do
    if exec 3<>/dev/tcp/127.0.0.1/6080 2>/dev/null; then
      printf 'GET /vnc.html HTTP/1.0\r\n\r\n' >&3
      head -1 <&3 | grep -q ' 200 ' && status=0
      exec 3<&-
      break
    fi
    sleep 1
  done
  for p in /proc/[0-9]*; do [[ $(readlink "$p/root" 2>/dev/null) == "$target" ]] && kill "${p#/proc/}" 2>/dev/null; done
  verdict=passed; ((status == 0)) || verdict=failed
  results+=("$label	$pretty	desktop :6080	0	$status	$verdict	noVNC's vnc.html served")
fi

echo
printf '%-10s %-32s %-16s %10s %6s  %s\n' release system command "wall time" exit result
for r in "${results[@]}"; do
  IFS=$'\t' read -r rel sys cmd secs st verdict tl <<<"$r"
  printf '%-10s %-32s %-16s %7dm%02ds %6s  %s %s\n' "$rel" "$sys" "$cmd" $((secs / 60)) $((secs % 60)) "$st" "$verdict" "$tl"
done
echo "(commit $commit; logs in $work; all runs so far: $work/results.tsv)"
for r in "${results[@]}"; do [[ $r == *$'\t'passed$'\t'* ]] || exit 1; done
