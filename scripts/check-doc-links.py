#!/usr/bin/env python3
"""Checks every link between the built site's pages (build/site by default): the page exists
and, for a link to a heading (#anchor), the page has an element with that id. mkdocs --strict
already fails on a link to a missing page; mkdocs 1.4 does not look at anchors, this does.
Prints each broken link and exits 1 if there is one. On Doxygen's pages (api/) only the pages
linked to are checked, not the anchors within them.

    check-doc-links.py [SITE_DIR]
"""
import html.parser
import pathlib
import sys
import urllib.parse


class Page(html.parser.HTMLParser):
    def __init__(self):
        super().__init__()
        self.ids, self.links = set(), []

    def handle_starttag(self, tag, attrs):
        attrs = dict(attrs)
        if attrs.get("id"):
            self.ids.add(attrs["id"])
        if tag == "a" and attrs.get("href"):
            self.links.append(attrs["href"])


def main():
    site = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else "build/site").resolve()
    pages = {}
    for path in site.rglob("*.html"):
        if path.name == "404.html":
            continue  # served for any missing address, its links are from the site's root
        page = Page()
        page.feed(path.read_text(encoding="utf-8"))
        pages[path] = page
    if not pages:
        print(f"check-doc-links: no pages in {site}")
        return 1
    broken = 0
    for path, page in sorted(pages.items()):
        # Doxygen's pages (api/): their pages must exist, but their own section anchors are
        # Doxygen's business (1.9.4 links "#nested-classes" on a class whose nested classes
        # are all private, and so not listed).
        generated = path.relative_to(site).parts[0] == "api"
        for href in page.links:
            url = urllib.parse.urlsplit(href)
            if url.scheme or url.netloc or href.startswith("mailto:"):
                continue  # the outside world is not checked here
            if url.path.startswith("/"):
                target = (site / url.path.lstrip("/")).resolve()
            else:
                target = (path.parent / url.path).resolve() if url.path else path
            if target.is_dir():
                target = target / "index.html"
            if target.suffix != ".html":
                if not target.exists():
                    print(f"{path.relative_to(site)}: {href}: no such file")
                    broken += 1
                continue
            if target not in pages:
                print(f"{path.relative_to(site)}: {href}: no such page")
                broken += 1
            elif (url.fragment and not generated
                  and urllib.parse.unquote(url.fragment) not in pages[target].ids):
                print(f"{path.relative_to(site)}: {href}: no heading #{url.fragment} there")
                broken += 1
    print(f"check-doc-links: {len(pages)} pages, {broken} broken links")
    return 1 if broken else 0


if __name__ == "__main__":
    sys.exit(main())
