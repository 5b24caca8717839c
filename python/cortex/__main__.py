import signal
import sys

from .cli import main

# Output piped into `head` and the like: end quietly when the reader stops reading.
signal.signal(signal.SIGPIPE, signal.SIG_DFL)
sys.exit(main())
