#!/usr/bin/env bash
# Bad command lines: exit status 2 and a message naming the option and the value (or that it
# is empty).
#   bad_command_lines.sh COINSPECT
set -euo pipefail
coinspect=$1
expect=$(dirname "$0")/expect.sh
bash "$expect" 2 "--seed: '-1' is not a seed" "$coinspect" scenario info slei-a --seed -1
bash "$expect" 2 "--seed: '99999999999999999999' is not a seed" \
  "$coinspect" scenario generate slei-a --seed 99999999999999999999 --out unused
bash "$expect" 2 "--seed: '1x' is not a seed" "$coinspect" run config.ini --seed 1x
bash "$expect" 2 "--seed: '-2' is not a seed" "$coinspect" demo --seed -2
bash "$expect" 2 "--seed: '-3' is not a seed" "$coinspect" score --scenario hangar --seed -3
bash "$expect" 0 "content hash" "$coinspect" scenario info slei-a --seed 18446744073709551615
bash "$expect" 2 "--fps: 'nan' is not a finite number from 0.01 to 1000" \
  "$coinspect" replay run.rawlog --fps nan
bash "$expect" 2 "--fps: 'inf' is not a finite number" "$coinspect" replay run.rawlog --fps inf
bash "$expect" 2 "--threads: Value -1 not in range 0 to 256" "$coinspect" run config.ini --threads -1
bash "$expect" 2 "--threads: Value two not in range" "$coinspect" run config.ini --threads two
bash "$expect" 2 "not expected: --bogus" "$coinspect" run config.ini --bogus
bash "$expect" 2 "bogus not in" "$coinspect" score --scenario hangar --mode bogus
# Empty paths (`--out ""` once wrote nothing and exited 0; `--scenario ""` was ignored).
bash "$expect" 2 "--out: an empty path" "$coinspect" run config.ini --out ""
bash "$expect" 2 "--scenario: an empty path" "$coinspect" eval run.rawlog --scenario ""
bash "$expect" 2 "--out: an empty path" "$coinspect" render run.rawlog --out ""
bash "$expect" 2 "--input: an empty path" "$coinspect" score --scenario hangar --input ""
bash "$expect" 2 "--out: an empty path" "$coinspect" plot-timeline --out "" run
echo "bad command lines: ok"
