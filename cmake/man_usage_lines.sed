# drape.1's usage block, one line per command: help2man fills the lines of `drape --help`'s
# "usage:" block into one paragraph; a line break (.br) after each keeps them apart.
/^usage: /,/^\.PP$/{
  /^\.IP$/d
  /^\.PP$/!s/$/\n.br/
}
