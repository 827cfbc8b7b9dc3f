"""scripts/check-doc-links.py, which `make docs` runs on the built site: a link to a missing
page or to a heading a page does not have fails it; a site whose links all land passes."""
import subprocess
import sys


def write_site(root, link):
    root.mkdir()
    (root / "index.html").write_text(f'<h1 id="top">Home</h1><a href="{link}">guide</a>')
    (root / "guide.html").write_text('<h2 id="units">Units</h2><a href="index.html#top">home</a>')


def check(source_dir, site):
    script = source_dir / "scripts" / "check-doc-links.py"
    return subprocess.run([sys.executable, str(script), str(site)], capture_output=True,
                          text=True)


def test_links_that_land_pass(source_dir, tmp_path):
    write_site(tmp_path / "site", "guide.html#units")
    result = check(source_dir, tmp_path / "site")
    assert result.returncode == 0, result.stdout
    assert result.stdout.strip() == "check-doc-links: 2 pages, 0 broken links"


def test_a_missing_heading_or_page_fails(source_dir, tmp_path):
    write_site(tmp_path / "anchor", "guide.html#scale")
    result = check(source_dir, tmp_path / "anchor")
    assert result.returncode == 1
    assert "index.html: guide.html#scale: no heading #scale there" in result.stdout
    write_site(tmp_path / "page", "guides.html")
    result = check(source_dir, tmp_path / "page")
    assert result.returncode == 1
    assert "index.html: guides.html: no such page" in result.stdout


def test_doxygen_pages_have_their_pages_checked_but_not_their_anchors(source_dir, tmp_path):
    site = tmp_path / "site"
    write_site(site, "guide.html#units")
    (site / "api").mkdir()
    (site / "api" / "class.html").write_text('<a href="#nested-classes">x</a>')
    assert check(source_dir, site).returncode == 0
    (site / "api" / "class.html").write_text('<a href="missing.html">x</a>')
    result = check(source_dir, site)
    assert result.returncode == 1
    assert "api/class.html: missing.html: no such page" in result.stdout
