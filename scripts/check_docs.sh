#!/usr/bin/env bash
# Checks that the documentation describes the product as it is, not how the work was done.
# Scans README.md and docs/**/*.md (not CHANGELOG.md, not bench/runs/) and prints FILE:LINE: TEXT
# for every line that carries:
#   - a calendar date (2026-12-05),
#   - "sitting" or "sittings",
#   - a work session ("this session", "sessions", "the H200 session", "second session", ...),
#   - a before/after story ("before/after", "against 3.9 s for the build before",
#     "before the fix"),
#   - a commit hash (7 to 40 hex digits in backticks or parentheses),
#   - an issue reference ("issue #12") or an issue's target ("the speed issue's target").
# Exits 1 when anything matched, 0 otherwise. Run it from anywhere: scripts/check_docs.sh
set -u
cd "$(dirname "$0")/.." || exit 2

patterns=(
  '\b(19|20)[0-9]{2}-[01][0-9]-[0-3][0-9]\b'
  '\bsittings?\b'
  '\b(this|that|each|every|one|a|an|the|next|last|first|second|third|fourth|fifth|sixth|earlier|later|previous|same|other|work|working|lab|GPU|H100|H200|device|benchmark|measurement)\s+sessions?\b(?!\s+panel)'
  '\bsessions\b'
  '\bsession.s\b'
  '\bbefore\s*/\s*after\b'
  '\bagainst\b[^.;:]*\b(builds?|code|commits?|versions?|shaders|programs|runs?|fix|change|sitting)\s+before\b'
  '\b(the|a|its|that)\s+(build|version|commit|code)\s+before\b'
  '\bbefore\s+(the|this|that|its)\s+(fix|change|commit|build|rewrite|patch)\b'
  '[`(](?=[0-9a-f]*[0-9])(?=[0-9a-f]*[a-f])[0-9a-f]{7,40}[`)]'
  '\bissues?\s*#[0-9]+'
  '\bissue.s\s+(target|limit|goal)'
)
regex=$(IFS='|'; echo "${patterns[*]}")

files=()
[ -f README.md ] && files+=(README.md)
while IFS= read -r -d '' f; do files+=("$f"); done < <(find docs -name '*.md' -print0 2>/dev/null | sort -z)

if [ ${#files[@]} -eq 0 ]; then
  echo "check_docs: no README.md or docs/*.md found" >&2
  exit 2
fi

hits=$(REGEX="$regex" perl -ne '
  BEGIN { $re = $ENV{REGEX} }
  my $line = $_;
  if ($line =~ /$re/i) { chomp $line; print "$ARGV:$.: $line\n" }
  close ARGV if eof;
' "${files[@]}")
if [ -n "$hits" ]; then
  echo "$hits"
  echo "check_docs: $(echo "$hits" | wc -l) line(s) above read as a lab notebook (dates, sittings," \
       "sessions, before/after, commit hashes, issue targets); describe the product as it is." >&2
  exit 1
fi
echo "check_docs: ${#files[@]} files clean"
exit 0
