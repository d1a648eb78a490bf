"""Text from a design (patch and mechanism names) made safe to print: control characters shown
as escapes, so a name cannot move the cursor, recolour the terminal or start a fake line."""


def printable(text):
    """`text` with every control character (C0, DEL, C1) written as a \\x.. escape."""
    return "".join(
        f"\\x{ord(c):02x}" if ord(c) < 0x20 or 0x7F <= ord(c) <= 0x9F else c for c in str(text)
    )


def printable_lines(text):
    """Each line of `text` made printable, the line breaks kept."""
    return "\n".join(printable(line) for line in str(text).split("\n"))
