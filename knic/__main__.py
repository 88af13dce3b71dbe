import sys

from knic.cli import main

sys.exit(main())
