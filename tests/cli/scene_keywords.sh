#!/bin/sh
# The scene language's word lists cannot drift: the reserved words in
# src/scene/scene_cur.c are sorted (bsearch, strcmp order) and unique; every
# upper-case word the parser compares against (statement tables, operand
# keywords, option names in src/scene/*.c) is reserved, so it can never be
# taken for a name; every reserved word is documented in docs/scene-format.md.
set -u
src=src/scene
doc=docs/scene-format.md
fail=0
words=$(mktemp) && lits=$(mktemp) || exit 1
trap 'rm -f "$words" "$words.sorted" "$lits"' EXIT
# The list: the string literals between "scene_cur_words[] = {" and "};".
sed -n '/scene_cur_words\[\] = {/,/};/p' "$src/scene_cur.c" | grep -oE '"[A-Z0-9]+"' | tr -d '"' > "$words"
n=$(wc -l < "$words")
[ "$n" -ge 80 ] || { echo "only $n reserved words found: the list's layout changed?" >&2; exit 1; }
LC_ALL=C sort -c "$words" || { echo "reserved words are not in strcmp order" >&2; fail=1; }
dups=$(LC_ALL=C sort "$words" | uniq -d)
[ -z "$dups" ] || { echo "reserved words listed twice: $dups" >&2; fail=1; }
# Words of two or more capitals quoted anywhere in the parser, but names the
# parser gives things itself (DEFAULT: the attribute of a deck without ATTR).
for f in "$src"/*.c; do
  [ "$f" = "$src/scene_cur.c" ] && continue
  grep -oE '"[A-Z][A-Z0-9]+"' "$f" | tr -d '"'
done | LC_ALL=C sort -u | grep -vx 'DEFAULT' > "$lits"
[ "$(wc -l < "$lits")" -ge 80 ] || { echo "too few parser keywords found" >&2; exit 1; }
LC_ALL=C sort -u "$words" > "$words.sorted"
missing=$(LC_ALL=C comm -23 "$lits" "$words.sorted")
[ -z "$missing" ] || { echo "keywords the parser uses but does not reserve:" $missing >&2; fail=1; }
undoc=""
while read -r w; do
  grep -qw -- "$w" "$doc" || undoc="$undoc $w"
done < "$words"
[ -z "$undoc" ] || { echo "reserved words not documented in $doc:$undoc" >&2; fail=1; }
exit $fail
