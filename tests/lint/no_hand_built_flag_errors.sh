#!/usr/bin/env bash
# The CLI names the flag of a refused value from the option itself
# (refuseOption, refuseWithoutEffect in apps/stochtex/common.h), so that no
# message spells a flag by hand and a renamed flag renames its errors: no
# InputError under ROOT may be built from text that starts with a flag
# ("--size ...", "-o ..."). Prints FILE:LINE: TEXT for each offender and
# exits 1. Comments are skipped. Usage: no_hand_built_flag_errors.sh ROOT
set -u
root=$1
[ -d "$root" ] || { echo "no such folder: $root"; exit 2; }
found=$(find "$root" \( -name '*.cpp' -o -name '*.h' \) -print0 | sort -z | xargs -0 perl -0777 -ne '
  my $text = $_;
  # Comments go (their newlines kept), string literals stay: one pass, so
  # "data/*.png" or "http://" in a string opens no comment.
  $text =~ s{("(?:\\.|[^"\\\n])*")|//[^\n]*|/\*.*?\*/}{ defined $1 ? $1 : ($& =~ tr/\n//cdr) }gse;
  # InputError(...), InputError{...} and InputError::overBudget(NAME, ...)
  # whose text starts with a flag.
  while ($text =~ /InputError\s*(?:::overBudget\s*\(\s*"[^"]*"\s*,|[({])\s*(?:std::string\s*\(\s*)?(?:"|R"\()(-[^"]*)"/g) {
    my ($flag, $line) = ($1, 1 + (substr($text, 0, $-[0]) =~ tr/\n//));
    (my $file = $ARGV) =~ s{^\Q'"$root"'\E/}{};
    print "$file:$line: \"$flag\"\n";
  }')
if [ -n "$found" ]; then
  echo "$found"
  echo "$(echo "$found" | wc -l) error(s) spell a flag by hand: refuse through the option (refuseOption)"
  exit 1
fi
echo "no hand-built flag in the errors under $root"
