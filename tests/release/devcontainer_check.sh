#!/usr/bin/env bash
# The dev container (.devcontainer/) is built in the same steps as the fresh-machine check
# (tools/fresh-check.sh), from the same files, with no copy of clothlab's package lists:
# - both take the base system from tools/base-packages.txt (the check's debootstrap --include, the
#   Dockerfile's first apt-get install reads the file itself);
# - the Dockerfile then runs `lab setup`, the function the README's commands install through in the
#   check; no package of lab's own lists is named in the Dockerfile;
# - it starts from Debian 13, every file it copies exists, devcontainer.json parses and names it.
# Then it proves it fails on a copy whose Dockerfile installs a copied package list.
# Usage: devcontainer_check.sh SOURCE_DIR
set -u
root=$1

check() {  # check TREE: prints what is wrong, returns 1 if anything is
  local t=$1 bad=0 df=$1/.devcontainer/Dockerfile p src
  say() { echo "$*"; bad=1; }
  [[ -f $df ]] || { echo ".devcontainer/Dockerfile: missing"; return 1; }
  grep -qE '^FROM debian:(trixie|13)' "$df" || say ".devcontainer/Dockerfile: FROM: not Debian 13"
  grep -q 'tools/base-packages.txt' "$t/tools/fresh-check.sh" || say "tools/fresh-check.sh: does not read tools/base-packages.txt"
  grep -qF 'include=(--include="$(IFS=,; echo "${base[*]}")")' "$t/tools/fresh-check.sh" \
    || say "tools/fresh-check.sh: debootstrap --include is not the base list"
  grep -qE '^RUN .*apt-get install .*base-packages\.txt' <(sed -e ':a' -e '/\\$/N; s/\\\n//; ta' "$df") \
    || say ".devcontainer/Dockerfile: the first install is not tools/base-packages.txt"
  grep -qE '^RUN [^ ]*/lab setup( |$)' "$df" || say ".devcontainer/Dockerfile: does not run lab setup"
  grep -q 'cmd_setup' "$t/lab" || say "lab: no cmd_setup"
  # no package of lab's lists copied into the Dockerfile
  for p in $(sed -n -E 's/^(CORE|RENDER|TEST|SLIDES)_PKGS=\((.*)\)$/\2/p' "$t/lab"); do
    grep -qE "(^|[[:space:]])$p([[:space:]]|$)" "$df" && say ".devcontainer/Dockerfile: installs $p itself (lab setup installs it)"
  done
  while read -r src; do
    [[ -e $t/$src ]] || say ".devcontainer/Dockerfile: COPY $src: no such file"
  done < <(awk '$1 == "COPY" { print $2 }' "$df")
  jq -e '.build.dockerfile == "Dockerfile" and .build.context == ".." and (.forwardPorts | index(6080))' \
    "$t/.devcontainer/devcontainer.json" >/dev/null || say ".devcontainer/devcontainer.json: build or port 6080 missing"
  bash -n "$t/.devcontainer/desktop.sh" || say ".devcontainer/desktop.sh: not valid bash"
  return $bad
}

check "$root" || { echo "FAIL: the dev container and the fresh-machine check part ways"; exit 1; }
# The check can fail: a Dockerfile that installs a copied package list.
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
mkdir -p "$tmp/tools" "$tmp/.devcontainer"
cp "$root/lab" "$tmp/"; cp "$root/tools/"* "$tmp/tools/"; cp "$root/.devcontainer/"* "$tmp/.devcontainer/"
sed -i 's|^RUN /opt/clothlab-setup/lab setup.*|RUN apt-get install -y libeigen3-dev libimgui-dev|' "$tmp/.devcontainer/Dockerfile"
if check "$tmp" >/dev/null; then echo "FAIL: a Dockerfile with its own package list passed the check"; exit 1; fi
echo "ok: the dev container installs through tools/base-packages.txt and lab setup, like the fresh-machine check"
