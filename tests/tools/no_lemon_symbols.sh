#!/bin/sh
# no_lemon_symbols.sh BINARY...: each binary's symbol tables (the full one and the dynamic one, which
# is what a stripped shared object keeps) name petersen's code and no LEMON entity: no lemon:: and
# no petersen::lemon_peer::. LEMON is the comparison peer of the tests and the bench; nothing
# shipped links it. A binary whose tables name no petersen:: symbol fails too: the check would
# pass on it without looking.
set -u
status=0
for binary in "$@"; do
  # nm says "no symbols" on stderr for a stripped table; the other table is still read.
  symbols=$( (nm -C "$binary"; nm -C -D "$binary") 2>/dev/null)
  total=$(printf '%s\n' "$symbols" | grep -c 'petersen::')
  if [ "$total" -eq 0 ]; then
    echo "$binary: no petersen:: symbol to look among (stripped?)"
    status=1
    continue
  fi
  lemon=$(printf '%s\n' "$symbols" | grep -E 'lemon(_peer)?::')
  if [ -n "$lemon" ]; then
    echo "$binary: $(printf '%s\n' "$lemon" | wc -l) LEMON symbols, among them:"
    printf '%s\n' "$lemon" | head -n 5
    status=1
  else
    echo "$binary: $total petersen:: symbols, no LEMON one"
  fi
done
exit "$status"
