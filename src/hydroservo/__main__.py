"""``python -m hydroservo``: the command line (:mod:`hydroservo.cli`)."""

import sys

from hydroservo.cli import main

if __name__ == "__main__":  # run, not imported (the API reference imports every module)
    sys.exit(main())
