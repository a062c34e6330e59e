# Sourced by the commands that make the pictures in docs/: each picture made is written down in
# docs/pictures.tsv with the command that made it, its CRC-32 and the names it shows, so that
# tests/pictures.rs can check that every picture was made by a command, was not replaced since, and
# shows no name that no longer exists.
#   record_picture PICTURE MAKER [NAME…]   PICTURE's line (docs/…png), made again; MAKER the
#                                          command (`cargo xtask …`); each NAME one the picture
#                                          shows: `file:PATH` (a file of the repository) or
#                                          `version:X.Y.Z` (the program's version)
#   program_version BINARY                 the version a built program says (`raytracer --version`)

record_picture() {
  local picture=$1 maker=$2 table=docs/pictures.tsv
  shift 2
  local names="${*:--}"
  local crc
  crc=$(python3 -c 'import sys, zlib; print("%08x" % zlib.crc32(open(sys.argv[1], "rb").read()))' "$picture")
  local rows
  rows=$(mktemp)
  {
    [ -f "$table" ] && grep -v -e '^#' -e "^${picture}	" "$table"
    printf '%s\t%s\t%s\t%s\n' "$picture" "$maker" "$crc" "$names"
  } | sort > "$rows" || true
  {
    echo "# Written by the commands that make the pictures (xtask/lib/pictures.sh); checked by tests/pictures.rs."
    printf '# picture\tmade by\tCRC-32\tnames it shows\n'
    cat "$rows"
  } > "$table"
  rm -f "$rows"
}

program_version() {
  "$1" --version | awk '{ print $2; exit }'
}
