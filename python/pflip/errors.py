"""PflipError: a pf_result other than PF_OK, with the library's own explanation."""
from ._types import Result


class PflipError(RuntimeError):
    """Raised when a pf_* call returns an error.

    code: the pf_result (a Result); function: the C function that failed; message: what the
    library's logger said during the call (its error text), else pf_result_string(code).
    """

    def __init__(self, function, code, message):
        self.function = function
        self.code = Result(code) if code in Result._value2member_map_ else code
        self.message = message
        name = self.code.name if isinstance(self.code, Result) else str(code)
        super().__init__(f"{function}: PF_{name}: {message}")
