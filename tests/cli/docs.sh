#!/bin/sh
# The documentation is true: every complete deck quoted in README.md and
# docs/*.md renders (and one introduced as `scenes/NAME.scene` is that file,
# card for card); every maprt command quoted there runs, in a scratch copy of
# the tree's scenes/, and the key=value figures and error lines quoted after
# it are what it prints (where a paragraph says the example comes from
# tests/cli/X.sh, that script's output is used). Commands with placeholders
# (SCENE, OUT.png, [options], a|b) are usage lines and are not run; make
# targets are not run here (they are the suite itself).
set -u
tmp=$(mktemp -d) || exit 1
trap 'rm -rf "$tmp"' EXIT
case $MAPRT in /*) ;; *) MAPRT=$PWD/$MAPRT ;; esac
src=$PWD
fail() { echo "docs.sh: $*" >&2; exit 1; }
mkdir "$tmp/blocks" "$tmp/work" && cp -R scenes "$tmp/work/" && mkdir "$tmp/work/out" || exit 1
# what `make demo` leaves in out/, small
(cd "$tmp/work" && $MAPRT render scenes/fig1.scene -o out/fig1.png --dl out/fig1.dl5080 --size 128x128 --quiet) \
  || fail "cannot render the demo's out/fig1.png"

# Split the docs into code blocks: fenced (```) or indented by 4 after a
# blank line. Each becomes blocks/N with blocks/N.where ("file:line") and
# blocks/N.intro (the six lines of prose before it).
for f in README.md docs/*.md; do
  awk -v f="$f" -v dir="$tmp/blocks" '
    function start(l) { blk = sprintf("%s/%s-%d", dir, gensub_safe(f), NR); inb = 1
                        print f ":" l > (blk ".where"); print p6 "\n" p5 "\n" p4 "\n" p3 "\n" p2 "\n" p1 > (blk ".intro") }
    function gensub_safe(s) { gsub(/[^A-Za-z0-9]/, "_", s); return s }
    function stop() { if (inb) { close(blk); close(blk ".where"); close(blk ".intro") } inb = 0; fence = 0 }
    /^```/ { if (fence) { stop(); next } stop(); start(NR + 1); fence = 1; next }
    fence { print > blk; next }
    /^    / && (inb || prev_blank) { if (!inb) start(NR); sub(/^    /, ""); print > blk; prev_blank = 0; next }
    { stop(); prev_blank = ($0 ~ /^[ \t]*$/); if (!prev_blank) { p6 = p5; p5 = p4; p4 = p3; p3 = p2; p2 = p1; p1 = $0 } }
  ' "$f"
done
nblocks=$(ls "$tmp/blocks" | grep -vc '\.')
[ "$nblocks" -gt 20 ] || fail "only $nblocks code blocks found in the docs"

# every file the docs name in backquotes exists (in the tree, docs/ or src/)
for f in README.md docs/*.md; do
  grep -o '`[A-Za-z0-9_./-]*\.\(md\|c\|h\|sh\|scene\|f90\|mk\)`' "$f" | tr -d '`' | sort -u | while read -r n; do
    case $n in .*) continue ;; esac                     # an extension, not a file
    grep -qx -- "$n" tests/cli/docs-external.txt && continue   # cited from elsewhere
    found=
    for d in . docs src tests */ src/*/ tests/*/ bench/*/; do [ -e "$d/$n" ] && found=1; done
    [ -n "$found" ] \
      || { echo "$f names \`$n\`, which does not exist"; exit 1; }
  done || fail "a doc names a missing file"
done

# record counts quoted for the shipped decks ("FIG1 SCENE A1  F  80  103
# records") are what cms list counts
$MAPRT cms list --disk A=scenes > "$tmp/list" 2> /dev/null || fail "cms list of scenes/ failed"
grep -h '^ *[A-Z0-9-]* *SCENE *A1 *F *80 *[0-9]* records' README.md docs/*.md | while read -r fn ft fm f l n rest; do
  real=$(awk -v fn="$fn" '$1 == fn && $2 == "SCENE" { print $6 }' "$tmp/list")
  [ "$real" = "$n" ] || { echo "the docs quote $fn SCENE with $n records; it has $real"; exit 1; }
done || fail "a quoted record count drifted"

decks=0; cmds=0; figures=0; skipped=0
for b in $(ls "$tmp/blocks" | grep -v '\.'); do
  blk="$tmp/blocks/$b"; where=$(cat "$blk.where")
  # --- a complete deck: it renders; a named one is the shipped file
  if grep -q '^ *EYE ' "$blk" && grep -q '^ *OBJECT ' "$blk"; then
    decks=$((decks + 1))
    cp "$blk" "$tmp/work/scenes/doc-deck.scene"
    (cd "$tmp/work" && $MAPRT render scenes/doc-deck.scene -o out/doc-deck.png --size 24x16 --quiet) \
      2> "$tmp/err" || fail "$where: the quoted deck does not render: $(cat "$tmp/err")"
    named=$(grep -o '`scenes/[a-z0-9-]*\.scene`' "$blk.intro" | tail -1 | tr -d '`')
    if [ -n "$named" ]; then
      sed 's/ *$//' "$blk" > "$tmp/a"; sed 's/ *$//' "$named" > "$tmp/b"
      cmp -s "$tmp/a" "$tmp/b" || fail "$where: the deck quoted as $named is not that file (diff: $(diff "$tmp/a" "$tmp/b" | head -3))"
    fi
    continue
  fi
  # --- commands, each with the lines quoted after it
  awk '
    /^(\$ )?(build\/)?maprt / { if (cmd != "") print cmd "\t" out; cmd = $0; out = ""; cont = /\\$/; next }
    cont { cmd = cmd " " $0; cont = /\\$/; next }
    cmd != "" { out = out "\034" $0 }
    END { if (cmd != "") print cmd "\t" out }' "$blk" | sed 's/\\ / /g' > "$tmp/cmds"
  while IFS='	' read -r cmd out; do
    cmd=$(printf '%s' "$cmd" | sed 's/^\$ //; s/^build\/maprt /maprt /; s/  *#.*$//')
    bare=$(printf '%s' "$cmd" | sed "s/'[^']*'//g")
    # usage lines: placeholders, options in brackets, alternatives
    if printf '%s' "$bare" | grep -q '[[|]\|\.\.\.\|[A-Z][A-Z][A-Z]'; then continue; fi
    cmds=$((cmds + 1))
    script=$(grep -o 'tests/cli/[a-z_0-9]*\.sh' "$blk.intro" | tail -1)
    if [ -n "$script" ]; then
      (MAPRT=$MAPRT sh "$src/$script") > "$tmp/out" 2> "$tmp/err" || fail "$where: $script failed"
    else
      (cd "$tmp/work" && eval "$MAPRT ${cmd#maprt }") > "$tmp/out" 2> "$tmp/err"; rc=$?
      missing=$(sed -n 's/^maprt: \([^:]*\): error: cannot open: No such file or directory$/\1/p' "$tmp/err")
      case $missing in
        ""|scenes/*|out/*) ;;
        *) echo "docs: $where: not run: needs your own $missing"; skipped=$((skipped + 1)); continue ;;
      esac
      if ! printf '%s' "$out" | tr '\034' '\n' | grep -q '^maprt: .*error: '; then
        [ $rc -eq 0 ] || fail "$where: '$cmd' exited $rc: $(cat "$tmp/err")"
      fi
    fi
    # the quoted figures: key=value (before any annotation) and error lines
    printf '%s' "$out" | tr '\034' '\n' | while read -r line; do
      case $line in
        maprt:*error:*) grep -qxF -- "$line" "$tmp/err" || { echo "$where: '$cmd' no longer prints: $line (it prints: $(cat "$tmp/err"))"; exit 1; } ;;
        [a-z]*=*) kv=${line%%[ 	]*}
                 grep -qxF -- "$kv" "$tmp/out" || { echo "$where: '$cmd' prints $(grep "^${kv%%=*}=" "$tmp/out"), not $kv"; exit 1; } ;;
      esac
    done > "$tmp/drift" || fail "$(cat "$tmp/drift")"
    figures=$((figures + $(printf '%s' "$out" | tr '\034' '\n' | grep -c '^[a-z][a-z_.]*=\|^maprt:.*error:')))
  done < "$tmp/cmds"
done
[ "$decks" -ge 1 ] || fail "no complete deck found (docs/scene-format.md quotes fig1 in full)"
[ "$cmds" -ge 3 ] || fail "only $cmds runnable commands found"
echo "docs: $nblocks code blocks, $decks decks rendered, $cmds commands run ($skipped needing the user's files), $figures quoted figures checked"
exit 0
