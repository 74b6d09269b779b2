#!/usr/bin/env bash
# The library speaks in parameters, the CLI adds flags: no string literal in a
# library source (*.cpp, *.h under ROOT) may name a CLI flag ("--aniso").
# Such a literal is, in practice, always a message ("--aniso must be ...")
# that belongs to the CLI; the library throws InputError::parameter("aniso",
# ...) and apps/stochtex maps the parameter to its flag. Comments may name
# flags. Prints FILE:LINE: "literal" for each offender and exits 1.
# Usage: no_flags_in_library.sh ROOT
set -u
root=$1
[ -d "$root" ] || { echo "no such folder: $root"; exit 2; }
offenders=0
count=0
while IFS= read -r -d '' file; do
  count=$((count + 1))
  # A small lexer: skips // and /* */ comments and character literals, and
  # collects "..." and R"delim(...)delim" literals with their first line.
  found=$(awk -v q="'" -v file="${file#"$root"/}" '
    function report(text, line) { if (text ~ /--[A-Za-z]/) printf "%s:%d: \"%s\"\n", file, line, text }
    BEGIN { state = "code" }
    {
      s = $0; n = length(s); i = 1
      if (state == "string") state = "code"   # an unterminated "..." ends with its line
      while (i <= n) {
        c = substr(s, i, 1)
        if (state == "block") {
          if (substr(s, i, 2) == "*/") { state = "code"; i += 2 } else i++
        } else if (state == "raw") {
          if (substr(s, i, length(rawEnd)) == rawEnd) { report(lit, litLine); state = "code"; i += length(rawEnd) }
          else { lit = lit c; i++ }
        } else if (state == "string") {
          if (c == "\\") { lit = lit substr(s, i, 2); i += 2 }
          else if (c == "\"") { report(lit, litLine); state = "code"; i++ }
          else { lit = lit c; i++ }
        } else if (substr(s, i, 2) == "//") {
          break
        } else if (substr(s, i, 2) == "/*") {
          state = "block"; i += 2
        } else if (c == "R" && substr(s, i + 1, 1) == "\"" && (i == 1 || substr(s, i - 1, 1) !~ /[A-Za-z0-9_]/)) {
          rest = substr(s, i + 2); p = index(rest, "(")
          rawEnd = ")" substr(rest, 1, p - 1) "\""
          state = "raw"; lit = ""; litLine = NR; i += 2 + p
        } else if (c == "\"") {
          state = "string"; lit = ""; litLine = NR; i++
        } else if (c == q) {
          # a character literal: skip it, so that a quote in it opens no string
          if (substr(s, i + 1, 1) == "\\") i += 4; else i += 3
        } else i++
      }
      if (state == "raw") lit = lit "\\n"  # shown escaped: one report line per literal
    }' "$file")
  if [ -n "$found" ]; then
    echo "$found"
    offenders=$((offenders + $(echo "$found" | wc -l)))
  fi
done < <(find "$root" \( -name '*.cpp' -o -name '*.h' \) -print0 | sort -z)

if [ "$offenders" -ne 0 ]; then
  echo "$offenders library string(s) name a CLI flag: throw InputError::parameter(\"name\", ...) and map the name to its flag in apps/stochtex/common.cpp"
  exit 1
fi
echo "no CLI flag in the string literals of $count library files"
