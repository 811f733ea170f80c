#!/bin/sh
# Doxygen input filter: a header's opening comment (the lines before `#pragma once`) is its contract; this turns it
# into the file's documentation block (/// lines ending in \file) without changing any line number.
exec sed -e '1,/^#pragma once/{
s|^//\(.*\)$|///\1|
s|^#pragma once$|/// \\file|
}' "$1"
