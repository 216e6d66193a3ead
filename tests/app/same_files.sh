# SPDX-License-Identifier: Apache-2.0
# Sourced by the shard tests: same_files A B passes when the two folders hold the same file names
# and every file is equal byte for byte, else prints the first difference and exits 1.
same_files() {
  diff <(cd "$1" && find . -type f | sort) <(cd "$2" && find . -type f | sort) ||
    { echo "FAIL: $1 and $2 hold different files"; exit 1; }
  local f
  while read -r f; do
    cmp "$1/$f" "$2/$f" || { echo "FAIL: $f differs"; exit 1; }
  done < <(cd "$1" && find . -type f)
}
