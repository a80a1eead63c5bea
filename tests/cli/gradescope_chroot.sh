#!/usr/bin/env bash
# End-to-end check of the Gradescope package in a chroot built from Debian packages (root only; minutes).
#   tests/cli/gradescope_chroot.sh AUTOGRADER_ZIP SUBMISSION_DIR WORKDIR [ROOTFS_TAR]
# Builds (or unpacks ROOTFS_TAR, made by `mmdebstrap --variant=minbase --include=ca-certificates,python3,python3-pip,
# curl,adduser,unzip bookworm root.tar`) a Debian bookworm root like Gradescope's base image, lays out /autograder
# as Gradescope does, runs setup.sh then run_autograder, and prints /autograder/results/results.json.
# Ubuntu's archive is not reachable from the machine this was written on, so the base is Debian bookworm (Python 3.11),
# not Ubuntu 22.04 (3.10) or 24.04 (3.12).
set -euo pipefail
ZIP=$(realpath "$1"); SUBMISSION=$(realpath "$2"); WORK=$3; TAR=${4:-}
ROOT="$WORK/root"
mkdir -p "$ROOT"
if [ -n "$TAR" ]; then
  tar -xf "$TAR" -C "$ROOT"
else
  mmdebstrap --variant=minbase --include=ca-certificates,python3,python3-pip,curl,adduser,unzip \
    bookworm "$ROOT" http://deb.debian.org/debian
fi
cleanup() {
  for m in proc dev/pts dev sys; do umount -l "$ROOT/$m" 2>/dev/null || true; done
}
trap cleanup EXIT
mount -t proc proc "$ROOT/proc"
mount --rbind /dev "$ROOT/dev"
mount --rbind /sys "$ROOT/sys"
cp /etc/resolv.conf "$ROOT/etc/resolv.conf"
# A network whose HTTPS goes through an inspecting proxy needs its CA inside the chroot too (pip reads PIP_CERT).
HOST_CA=${PIP_CERT:-/etc/ssl/certs/ca-certificates.crt}
[ -f "$HOST_CA" ] && cp "$HOST_CA" "$ROOT/usr/local/share/host-ca.crt"
mkdir -p "$ROOT/autograder/source" "$ROOT/autograder/submission" "$ROOT/autograder/results"
(cd "$ROOT/autograder/source" && python3 -m zipfile -e "$ZIP" .)
cp -r "$SUBMISSION/." "$ROOT/autograder/submission/"
chmod +x "$ROOT/autograder/source/setup.sh" "$ROOT/autograder/source/run_autograder"
cp "$ROOT/autograder/source/run_autograder" "$ROOT/autograder/run_autograder"
echo '{"id": 1, "assignment": {"total_points": 10}}' > "$ROOT/autograder/submission_metadata.json"
# Gradescope runs setup.sh from the source folder while building the image, then run_autograder for each submission.
ENV=(/usr/bin/env -i PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin HOME=/root)
[ -f "$ROOT/usr/local/share/host-ca.crt" ] && ENV+=(PIP_CERT=/usr/local/share/host-ca.crt)
chroot "$ROOT" "${ENV[@]}" bash -c 'cd /autograder/source && ./setup.sh' > "$WORK/setup.log" 2>&1 || { tail -30 "$WORK/setup.log"; exit 1; }
start=$(date +%s)
chroot "$ROOT" "${ENV[@]}" bash -c 'cd /autograder && ./run_autograder' > "$WORK/run.log" 2>&1
echo "run_autograder: $(( $(date +%s) - start )) s"
cat "$ROOT/autograder/results/results.json"
