"""Names of the fields of a title block (what a scene's [title_block] may fill)."""

#: fields of a sheet's title block that a scene may fill ([title_block])
TITLE_BLOCK_FIELDS = (
    "title", "author", "group", "instructor", "school", "department", "date", "scale",
    "sheet_number", "sheets_total", "designation", "document_type", "material", "litera",
)
