"""Only what pyproject.toml cannot say: the user guide (``docs/*.md`` and its figures) goes into the wheel as
``hydroservo/docs``, so that the pages the package's messages name exist where it is installed
(``hydroservo docs`` lists them). The guide stays in one place in the repository."""

import shutil
from pathlib import Path

from setuptools import setup
from setuptools.command.build_py import build_py


class BuildWithGuide(build_py):
    """build_py, then the guide copied into the built package."""

    def run(self) -> None:
        super().run()
        here = Path(__file__).resolve().parent / "docs"
        target = Path(self.build_lib) / "hydroservo" / "docs"
        if not here.is_dir():  # building from an sdist without the guide: nothing to copy
            return
        shutil.rmtree(target, ignore_errors=True)  # no page left over from an earlier build
        target.mkdir(parents=True)
        for page in here.glob("*.md"):
            if page.name in ("index.md", "api.md"):  # the site's own pages (directives, no guide)
                continue
            shutil.copyfile(page, target / page.name)
        if (here / "img").is_dir():
            shutil.copytree(here / "img", target / "img", dirs_exist_ok=True)


setup(cmdclass={"build_py": BuildWithGuide})
