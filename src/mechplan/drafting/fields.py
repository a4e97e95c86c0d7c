"""What a scene may choose for its drawing: paper size, standard, the fields of a title block."""

#: paper sizes and drawing standards a scene's [drawing] may choose
SHEETS = ("A0", "A1", "A2", "A3", "A4")
STANDARDS = ("iso", "gost", "tcvn")

#: fields of a sheet's title block that a scene may fill ([title_block])
TITLE_BLOCK_FIELDS = (
    "title", "author", "group", "instructor", "school", "department", "date", "scale",
    "sheet_number", "sheets_total", "designation", "document_type", "material", "litera",
)
