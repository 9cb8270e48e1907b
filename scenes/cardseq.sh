#!/bin/sh
# Renumbers scene decks as 80-column card images: columns 1-72 hold the text
# (longer text is refused), 73-80 a sequence field of a 4-letter deck tag and a
# number counting by 10. Usage: sh scenes/cardseq.sh TAG FILE  (rewrites FILE)
tag=$1; f=$2
[ -n "$tag" ] && [ -f "$f" ] || { echo "usage: cardseq.sh TAG FILE" >&2; exit 2; }
awk -v tag="$tag" '
{ t = substr($0, 1, 72); sub(/[ ]+$/, "", t)
  if (length($0) > 72 && substr($0, 73) !~ /^[A-Z0-9 ]*$/) { print "line " NR " is longer than 72 columns" > "/dev/stderr"; exit 1 }
  printf "%-72s%-4s%04d\n", t, substr(tag "    ", 1, 4), NR * 10 }' "$f" > "$f.tmp" && mv "$f.tmp" "$f"
