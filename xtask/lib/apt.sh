# Sourced by the chores that install Debian packages where they are missing.
#   apt_install PACKAGE…           installs these packages with apt-get (as root, or through sudo)
#   apt_install_missing PACKAGE…   installs those of them dpkg does not know as installed; nothing
#                                  when all are, or where there is no dpkg (not Debian or Ubuntu)

apt_install() {
  [ $# -gt 0 ] || return 0
  local sudo=""
  [ "$(id -u)" -ne 0 ] && sudo="sudo"
  echo "installing: $*"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "$@"
}

apt_install_missing() {
  command -v dpkg >/dev/null 2>&1 || return 0
  local missing=() package
  for package in "$@"; do
    dpkg -s "$package" >/dev/null 2>&1 || missing+=("$package")
  done
  apt_install "${missing[@]}"
}
