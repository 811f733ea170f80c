// Where the writers put their text: a std::ostream (RTL's stream calls) or a std::string. The writers are templates
// on the target and append through textAppend, so a program that writes only to strings instantiates no stream and
// links none of the standard library's stream and locale machinery (its size is given in docs/io.md, "Writing
// without streams").
#pragma once

#include <ostream>
#include <string>

namespace rtl::detail
{
    inline void textAppend(std::string &out, const std::string &text) { out += text; }
    inline void textAppend(std::string &out, const char *text) { out += text; }
    // operator<< (not write): the stream's width and fill apply as they always did.
    inline void textAppend(std::ostream &out, const std::string &text) { out << text; }
    inline void textAppend(std::ostream &out, const char *text) { out << text; }
}

namespace rtl::detail
{
    //! What write(std::string &) appends to an empty string: the writers' string forms.
    template<class Write>
    std::string textString(Write &&write)
    {
        std::string out;
        write(out);
        return out;
    }

    //! `<<` of text onto either target, piece by piece as the writers always wrote to streams.
    template<class Out>
    struct TextOut
    {
        Out &out;
        TextOut &operator<<(const std::string &text)
        {
            textAppend(out, text);
            return *this;
        }
        TextOut &operator<<(const char *text)
        {
            textAppend(out, text);
            return *this;
        }
    };
}
