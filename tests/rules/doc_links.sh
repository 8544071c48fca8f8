#!/usr/bin/env bash
# CTest doc_links: every relative link and image in README.md, docs/*.md and docs/reports/*.md names a file that
# exists, and every #anchor (in the same file or another .md) names a heading there, as GitHub
# makes them (lower case, punctuation dropped, spaces to hyphens, -1, -2 for repeats).
# Links to http(s):, mailto: and the like are not checked; code spans and blocks are skipped.
# Usage: doc_links.sh SOURCE_DIR
set -u
cd "$1" || exit 2
perl -e '
use strict; use warnings;
my %anchors;  # file -> { anchor -> 1 }
sub slurp { my ($f) = @_; open my $h, "<", $f or return undef; local $/; my $t = <$h>; close $h; $t }
sub strip_fences {  # fenced code blocks out, line count kept
  my ($t) = @_;
  $t =~ s{^(```|~~~).*?^\1[^\n]*$}{ my $b = $&; $b =~ s/[^\n]//g; $b }gmse;
  return $t;
}
sub strip_code {  # and inline code spans
  my ($t) = strip_fences(@_);
  $t =~ s{`[^`\n]*`}{}g;
  return $t;
}
sub anchors_of {
  my ($f) = @_;
  return $anchors{$f} if $anchors{$f};
  my $t = slurp($f); my %a; my %seen;
  if (defined $t) {
    $t = strip_fences($t);
    for my $line (split /\n/, $t) {
      next unless $line =~ /^#{1,6}\s+(.*?)\s*#*\s*$/;
      my $s = lc $1;
      $s =~ s/<[^>]*>//g;               # inline html
      $s =~ s/\[([^\]]*)\]\([^)]*\)/$1/g; # links keep their text
      $s =~ s/[^\p{L}\p{N}\s_-]//g;     # punctuation out
      $s =~ s/ /-/g;
      my $n = $seen{$s}++;
      $a{$n ? "$s-$n" : $s} = 1;
    }
    while ($t =~ /<a\s+(?:name|id)="([^"]+)"/g) { $a{$1} = 1 }
  }
  return $anchors{$f} = \%a;
}
my ($bad, $n) = (0, 0);
for my $file (@ARGV) {
  my $t = strip_code(slurp($file));
  (my $dir = $file) =~ s{[^/]*$}{};
  my $line = 1;
  for my $l (split /\n/, $t, -1) {
    my @targets;
    push @targets, $1 while $l =~ /!?\[[^\]]*\]\(\s*<?([^)\s>]+)>?(?:\s+"[^"]*")?\s*\)/g;
    push @targets, $1 while $l =~ /<(?:img|a)\s[^>]*(?:src|href)="([^"]+)"/g;
    for my $target (@targets) {
      next if $target =~ m{^[a-z][a-z0-9+.-]*:}i;   # http:, https:, mailto:
      $n++;
      my ($path, $anchor) = $target =~ /^([^#]*)(?:#(.*))?$/;
      my $dest = $path eq "" ? $file : $dir . $path;
      $dest =~ s{/\./}{/}g;
      if ($path ne "" && !-e $dest) {
        print "FAILED: $file:$line: link to $target: no file $dest\n"; $bad++; next;
      }
      if (defined $anchor && $anchor ne "") {
        if ($dest !~ /\.md$/) { print "FAILED: $file:$line: #$anchor into $dest, which has no headings\n"; $bad++; next }
        if (!anchors_of($dest)->{$anchor}) {
          print "FAILED: $file:$line: link to $target: $dest has no heading #$anchor\n"; $bad++;
        }
      }
    }
    $line++;
  }
}
print "doc_links: $n relative links checked, $bad broken\n";
exit($bad ? 1 : 0);
' README.md docs/*.md docs/reports/*.md
