"""``python -m hydroservo``: the command line (:mod:`hydroservo.cli`)."""

import sys

from hydroservo.cli import main

sys.exit(main())
