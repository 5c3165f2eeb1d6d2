# Sourced by the tests that compare two outputs. h5_same A B GROUP...: every dataset under each GROUP
# agrees bit for bit between the HDF5 files A and B. h5diff exits 0 on datasets it cannot compare
# (other shapes or types; it prints "Not comparable" and compares nothing): that counts as a
# difference here, except a dataset empty in both files.
h5_same() {
  local a=$1 b=$2 group report line path; shift 2
  for group in "$@"; do
    report=$(h5diff -c "$a" "$b" "$group" "$group" 2>&1) || return 1
    while IFS= read -r line; do
      path=$(sed -n 's/^Not comparable: <\([^>]*\)> or <[^>]*> is an empty dataset$/\1/p' <<< "$line")
      [ -n "$path" ] && [ "$(h5ls "$a/$path" | cut -c 25-)" = "$(h5ls "$b/$path" | cut -c 25-)" ] || return 1
    done < <(grep -i "not comparable" <<< "$report")
  done
}
