#!/usr/bin/env bash
# Keeps the README's and docs/'s commands true: runs every command line of
# their ```sh blocks that starts with `build/icpbench` or `sqlite3`, and checks
# every relative link. Usage: doc_commands_test.sh SOURCE_DIR BUILD_DIR
#
# The convention the pages follow (docs/README.md, "Writing docs"):
# - ```text: a synopsis with placeholders; not run.
# - ```sh: concrete commands; run from a scratch folder laid out like the
#   repository root (build/, examples/, specs/, docs/, problems/,
#   experiments/, an empty results/), in page order (README.md, then
#   docs/cli.md, then the other pages by path), so a page may use a store an
#   earlier command wrote. Each must exit 0 within ICPBENCH_DOC_TIMEOUT
#   seconds (default 120).
# - A ```sh block right after a line `<!-- not run: REASON -->` is not run
#   (slow, or needs a cluster); the reason is required.
set -uo pipefail
src=$(cd "${1:?SOURCE_DIR}" && pwd)
build=$(cd "${2:?BUILD_DIR}" && pwd)
limit=${ICPBENCH_DOC_TIMEOUT:-120}

scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
ln -s "$build" "$scratch/build"
for d in examples specs docs problems experiments; do ln -s "$src/$d" "$scratch/$d"; done
mkdir "$scratch/results"

pages=("$src/README.md")
[ -f "$src/docs/cli.md" ] && pages+=("$src/docs/cli.md")
while IFS= read -r page; do
  [ "$page" = "$src/docs/cli.md" ] || pages+=("$page")
done < <(find "$src/docs" -name '*.md' | LC_ALL=C sort)

passed=0
failed=0
fail() {
  echo "FAIL $1"
  failed=$((failed + 1))
}

# Prints "LINE<TAB>COMMAND" for each command to run, or "LINE<TAB>!message"
# for a malformed block; a command continued with a trailing backslash is
# joined into one line.
extract() {
  awk '
    function flush() { if (cmd != "") { print start "\t" cmd; cmd = "" } }
    /^[ \t]*```/ {
      if (!in_block) {
        in_block = 1
        run = ($0 ~ /^[ \t]*```sh[ \t]*$/) && !skip
        if (skip && $0 !~ /^[ \t]*```sh/) print NR "\t!not-run marker before a non-sh block"
        skip = 0
      } else { flush(); in_block = 0; run = 0 }
      next
    }
    in_block && run {
      line = $0
      if (cmd != "") { sub(/^[ \t]+/, "", line); cmd = cmd " " line }
      else if (line ~ /^(build\/icpbench|sqlite3)[ \t]/) { cmd = line; start = NR }
      else next
      if (cmd ~ /\\$/) { sub(/\\$/, "", cmd) } else flush()
      next
    }
    !in_block && /^<!-- not run:/ {
      if ($0 !~ /^<!-- not run: *[^ ].*-->/) print NR "\t!not-run marker without a reason"
      skip = 1; next
    }
    !in_block && NF { skip = 0 }
  ' "$1"
}

# The anchors of a page's headings, as GitHub makes them: lower case, spaces
# to hyphens, other punctuation dropped (outside fenced blocks).
slugs() {
  awk '/^[ \t]*```/ { f = !f; next } !f && /^#+ / { sub(/^#+ /, ""); print }' "$1" |
    tr '[:upper:]' '[:lower:]' | sed 's/[^a-z0-9 _-]//g; s/ /-/g'
}

for page in "${pages[@]}"; do
  rel=${page#"$src/"}
  while IFS=$'\t' read -r line cmd; do
    [ -n "$line" ] || continue
    if [ "${cmd:0:1}" = "!" ]; then
      fail "$rel:$line: ${cmd:1}"
      continue
    fi
    if out=$(cd "$scratch" && timeout "$limit" bash -c "$cmd" 2>&1 </dev/null); then
      passed=$((passed + 1))
    else
      fail "$rel:$line: exit $?: $cmd"
      printf '%s\n' "$out" | tail -n 15 | sed 's/^/    /'
    fi
  done < <(extract "$page")

  # Relative links ([text](path), [text](path#anchor), [text](#anchor)) must
  # name a file, and an anchor a heading of the Markdown page it points to.
  while IFS= read -r target; do
    path=${target%%#*}
    anchor=""
    [ "$path" != "$target" ] && anchor=${target#*#}
    file=$page
    [ -n "$path" ] && file="$(dirname "$page")/$path"
    if [ ! -e "$file" ]; then
      fail "$rel: broken link to $target"
    elif [ -n "$anchor" ] && [ -f "$file" ] && [[ "$file" == *.md ]] &&
         ! slugs "$file" | grep -qxF -- "$anchor"; then
      fail "$rel: link to $target: no such heading"
    else
      passed=$((passed + 1))
    fi
  done < <(grep -o '\](\([^)#:]*\)\(#[^)]*\)\?)' "$page" | sed 's/^](\(.*\))$/\1/')
done

echo "doc commands and links: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
