"""crawlsim.errors: the one exception the package raises for bad input and failed runs.

Owns `Error` (carries the C library's message, its status code and name, when the failure
came from libcrawlsim; a plain message for what the package checks itself).
"""


class Error(Exception):
    """A failure of crawlsim: bad input (a value out of range, a missing file), a failed step,
    a step after a failure. `status` is the C status code (negative; 0 when the package itself
    refused the input), `status_name` its name (e.g. "CS_ERR_RANGE") and str(e) the one-line
    message naming the file, line and cause."""

    def __init__(self, message, status=0, status_name=""):
        super().__init__(message)
        self.status = status
        self.status_name = status_name
