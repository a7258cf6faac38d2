#!/usr/bin/python3
"""Every relative link of README.md and docs/*.md resolves: the file exists and, for a link
with #anchor, the Markdown file it names has a heading with that anchor (GitHub's rule).

usage: doc_links.py SOURCE_DIR    (ctest `docs.links`; prints each broken link, exits 1)
Standard library only. Links inside code (fenced blocks, `spans`) are text, not links.
"""
import collections
import glob
import os
import re
import sys

LINK = re.compile(r"!?\[[^\]]*\]\(([^)\s]+)(?:\s+\"[^\"]*\")?\)")
CODE = re.compile(r"```.*?```|`[^`\n]*`|<!--.*?-->", re.S)


def anchors(path):
    """GitHub's anchors of a Markdown file's headings: lower case, punctuation dropped, spaces
    as hyphens, a repeated one numbered -1, -2, ..."""
    seen, out = collections.Counter(), set()
    text = re.sub(r"```.*?```", "", open(path, encoding="utf-8").read(), flags=re.S)
    for line in text.splitlines():
        m = re.match(r"#{1,6}\s+(.*?)\s*#*\s*$", line)
        if not m:
            continue
        slug = re.sub(r"[^\w\- ]", "", m.group(1).replace("`", "").lower()).replace(" ", "-")
        out.add(slug if not seen[slug] else "%s-%d" % (slug, seen[slug]))
        seen[slug] += 1
    return out


def broken(root):
    files = [os.path.join(root, "README.md")] + sorted(glob.glob(os.path.join(root, "docs", "*.md")))
    for md in files:
        text = CODE.sub("", open(md, encoding="utf-8").read())
        for target in LINK.findall(text):
            if re.match(r"[a-z][a-z0-9+.-]*:", target):  # http:, https:, mailto: ...
                continue
            path, _, anchor = target.partition("#")
            dest = os.path.normpath(os.path.join(os.path.dirname(md), path)) if path else md
            where = os.path.relpath(md, root) + ": " + target
            if not os.path.exists(dest):
                yield where + " (no such file)"
            elif anchor and dest.endswith(".md") and anchor not in anchors(dest):
                yield where + " (no such heading)"


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    bad = list(broken(sys.argv[1]))
    for b in bad:
        print("broken link: " + b)
    print("doc_links: %d broken" % len(bad))
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
