# Sourced by the end-to-end tests that write pictures (render, plot-features, plot-timeline).
# check_png FILE WIDTH HEIGHT: the PNG signature, then IHDR's width and height (big-endian).
check_png() {
  local signature size
  signature=$(od -An -tx1 -N8 "$1" | tr -d ' \n')
  [[ $signature == 89504e470d0a1a0a ]] || { echo "$1 is not a PNG"; exit 1; }
  size=$(od -An -tu1 -j16 -N8 "$1" | awk '{ print $1*16777216+$2*65536+$3*256+$4 "x" $5*16777216+$6*65536+$7*256+$8 }')
  [[ $size == "$2x$3" ]] || { echo "$1 is $size, expected $2x$3"; exit 1; }
}
