"""The exceptions of the axcheck package."""

from typing import Optional


class ReadError(ValueError):
    """A measurement file that could not be read.

    The message names the file, the line (or a workbook's sheet and cell) and what was
    expected, as the command line's does; the parts are attributes for a program.
    """

    def __init__(
        self,
        message: str,
        path: str,
        line: Optional[int] = None,
        column: Optional[int] = None,
        sheet: Optional[str] = None,
        field: Optional[str] = None,
    ) -> None:
        super().__init__(message)
        self.message = message
        #: The file as given.
        self.path = path
        #: 1-based line (a workbook's row), when the failure is on one.
        self.line = line
        #: 1-based column, when known.
        self.column = column
        #: The workbook's sheet, for XLSX files.
        self.sheet = sheet
        #: The column, key or section the failure is about (`deviation_um`, `direction`).
        self.field = field

    def __str__(self) -> str:
        return self.message
