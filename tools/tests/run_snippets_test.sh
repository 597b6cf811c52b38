#!/bin/sh
# The self-test of tools/run-snippets: a Markdown file with a passing and a failing
# runnable snippet, and one with a runnable mark on a non-shell fence. Each check prints
# what it expected when it fails.
runner=$(dirname "$0")/../run-snippets
dir=$(mktemp -d) || exit 1
trap 'rm -rf "$dir"' EXIT
fail() { echo "run_snippets_test: $*"; exit 1; }

cat > "$dir/two.md" <<'MD'
# Two snippets
<!-- runnable -->
```sh
echo passing > passed.txt
```
Not runnable:
```sh
exit 9
```
<!-- runnable -->
```bash
echo about to fail
exit 7
```
MD
out=$("$runner" --dir "$dir" "$dir/two.md"); status=$?
[ "$status" = 1 ] || fail "a failing snippet must make the runner exit 1, not $status; output: $out"
echo "$out" | grep -qF "$dir/two.md:3: ok" || fail "expected '$dir/two.md:3: ok' in: $out"
echo "$out" | grep -qF "$dir/two.md:11: failed (exit 7)" || fail "expected '$dir/two.md:11: failed (exit 7)' in: $out"
echo "$out" | grep -qF "about to fail" || fail "expected the failing snippet's output in: $out"
[ -f "$dir/passed.txt" ] || fail "the snippet did not run in --dir $dir"

out=$("$runner" --list "$dir/two.md"); status=$?
[ "$status" = 0 ] || fail "--list must exit 0, not $status"
[ "$(echo "$out" | wc -l)" = 2 ] || fail "--list must list the 2 runnable snippets, not: $out"

printf '# One\n<!-- runnable -->\n```sh\ntrue\n```\n' > "$dir/one.md"
out=$("$runner" --dir "$dir" "$dir/one.md"); status=$?
[ "$status" = 0 ] || fail "a passing file must exit 0, not $status; output: $out"

printf '# Tagged\n<!-- runnable: solved -->\n```sh\necho solved > solved.txt\n```\n' > "$dir/tagged.md"
out=$("$runner" --dir "$dir" "$dir/tagged.md"); status=$?
[ "$status" = 0 ] && [ ! -f "$dir/solved.txt" ] || fail "a snippet marked runnable: solved must not run without --tag solved"
out=$("$runner" --dir "$dir" --tag solved "$dir/tagged.md"); status=$?
[ "$status" = 0 ] && [ -f "$dir/solved.txt" ] || fail "--tag solved must run the snippet marked runnable: solved; output: $out"

printf 'text\n<!-- runnable -->\n```tcl\nputs x\n```\n' > "$dir/bad.md"
out=$("$runner" "$dir/bad.md" 2>&1); status=$?
[ "$status" = 2 ] || fail "a runnable mark on a tcl fence must exit 2, not $status"
echo "$out" | grep -qF "$dir/bad.md:2:" || fail "expected the mark's FILE:LINE '$dir/bad.md:2:' in: $out"
echo "run_snippets_test: ok"
