"""``python -m solvers …`` as documented: the command line lives in ``cli`` (it imports every
package, so it cannot live inside the numerical core); this entry point only hands over."""

import sys

from cli import main

sys.exit(main())
