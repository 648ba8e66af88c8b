#!/bin/sh
# tests/web_imports.sh MODULE.wasm
#
# Prints the imports of a WebAssembly module, "module.name" separated by
# spaces (with the kind: func, table, memory, global), or "none" when it has
# no import section or an empty one.  Reads the binary format directly
# (magic, version, then sections: id byte, LEB128 size, payload; the import
# section has id 2), with od and awk only.  Exit status 1 if the file is not
# a WebAssembly module.
od -An -v -tu1 "$1" | awk '
{ for (i = 1; i <= NF; i++) b[n++] = $i + 0 }
function leb(   v, s, x) { v = 0; s = 1; do { x = b[p++]; v += (x % 128) * s; s *= 128 } while (x >= 128 && p < n); return v }
function name(   len, str, k) { len = leb(); str = ""; for (k = 0; k < len; k++) str = str sprintf("%c", b[p++]); return str }
function limits(   f) { f = b[p++]; leb(); if (f % 2 == 1) leb() }
END {
    if (n < 8 || b[0] != 0 || b[1] != 97 || b[2] != 115 || b[3] != 109) { print "not a WebAssembly module"; exit 1 }
    p = 8; out = ""
    while (p < n) {
        id = b[p++]; size = leb(); end = p + size
        if (id == 2) {
            count = leb()
            for (j = 0; j < count; j++) {
                mod = name(); fld = name(); kind = b[p++]
                if (kind == 0) { leb(); k = "func" }
                else if (kind == 1) { p++; limits(); k = "table" }
                else if (kind == 2) { limits(); k = "memory" }
                else { p += 2; k = "global" }
                out = out (out == "" ? "" : " ") mod "." fld "(" k ")"
            }
        }
        p = end
    }
    print (out == "" ? "none" : out)
}'
