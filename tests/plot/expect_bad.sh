# Sourced by the plot commands' end-to-end tests, which set $coinspect, $out and $picture_command.
# expect_bad REGEX ARGS...: `coinspect $picture_command --out $out/bad.png ARGS...` exits 2, its
# stderr matches REGEX, and no picture is written.
expect_bad() {
  local regex=$1 status
  shift
  rm -f "$out/bad.png"
  set +e
  "$coinspect" "$picture_command" --out "$out/bad.png" "$@" > /dev/null 2> "$out/bad.err"
  status=$?
  set -e
  cat "$out/bad.err"
  [[ $status -eq 2 ]] || { echo "$picture_command $*: exit status $status, expected 2"; exit 1; }
  grep -Eq -- "$regex" "$out/bad.err" || { echo "$picture_command $*: no match for: $regex"; exit 1; }
  [[ ! -e $out/bad.png ]] || { echo "$picture_command $*: wrote a picture"; exit 1; }
}
