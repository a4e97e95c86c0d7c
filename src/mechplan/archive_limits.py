"""The limits every archive and container a user hands in is read within (a Moodle or Canvas
download, a workbook, a PDF's attachments): one place, no imports, so that `mechplan --help`
builds its options without loading the readers."""

#: most entries of an archive (nested ones counted too)
MAX_ENTRIES = 20_000
#: most bytes of all members together, uncompressed (nested ones counted too)
MAX_TOTAL = 512 * 1024**2
#: most bytes of one member
MAX_MEMBER = 64 * 1024**2
#: largest compression ratio of a member bigger than RATIO_FLOOR (DXF text compresses ~10–30×)
MAX_RATIO = 200
RATIO_FLOOR = 1024**2
