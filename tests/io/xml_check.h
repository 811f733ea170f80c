// A small well-formedness checker for the SVG the writers produce (no DTDs, no CDATA, no comments needed):
// balanced and properly nested elements, one root, quoted unique attributes, only the five predefined entities and
// character references, no raw '<' or '&' in text, valid UTF-8 without control characters.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "rtl/io/LaTeXUtility.h"

namespace xml_check
{
    struct Result
    {
        bool ok = false;
        std::string error;
        std::map<std::string, size_t> elements;   // element name -> count
        std::vector<std::string> texts;           // character data of <text> elements (entities kept)
    };

    inline bool nameChar(char c)
    {
        return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '-' || c == '_' ||
               c == ':' || c == '.';
    }

    inline bool validReference(const std::string &s, size_t &i)
    {
        size_t semi = s.find(';', i);
        if (semi == std::string::npos || semi - i > 10)
            return false;
        std::string ref = s.substr(i + 1, semi - i - 1);
        bool ok = ref == "amp" || ref == "lt" || ref == "gt" || ref == "quot" || ref == "apos";
        if (!ok && ref.size() > 1 && ref[0] == '#')
            ok = ref.find_first_not_of(ref[1] == 'x' ? "0123456789abcdefABCDEF" : "0123456789", ref[1] == 'x' ? 2 : 1) ==
                 std::string::npos;
        i = semi;
        return ok;
    }

    inline Result check(const std::string &s)
    {
        Result r;
        auto fail = [&](const std::string &e, size_t at) {
            r.error = e + " at " + std::to_string(at);
            return r;
        };
        if (rtl::LaTeX::sanitizeUtf8(s) != s)
        {
            // Newlines and tabs are fine in XML; sanitizeUtf8 turns them into spaces, so compare without them.
            std::string t;
            for (char c : s)
                t += (c == '\n' || c == '\t' || c == '\r') ? ' ' : c;
            if (rtl::LaTeX::sanitizeUtf8(s) != t)
                return fail("invalid UTF-8 or control character", 0);
        }
        std::vector<std::string> stack;
        size_t i = 0, roots = 0;
        if (s.rfind("<?xml", 0) == 0)
        {
            i = s.find("?>");
            if (i == std::string::npos)
                return fail("unterminated declaration", 0);
            i += 2;
        }
        std::string text;
        while (i < s.size())
        {
            char c = s[i];
            if (c == '&')
            {
                size_t b = i;
                if (!validReference(s, i))
                    return fail("bad reference", i);
                if (!stack.empty() && stack.back() == "text")
                    text += s.substr(b, i + 1 - b);
                ++i;
                continue;
            }
            if (c != '<')
            {
                if (stack.empty() && c != ' ' && c != '\n')
                    return fail("text outside the root", i);
                if (!stack.empty() && stack.back() == "text")
                    text += c;
                ++i;
                continue;
            }
            bool closing = i + 1 < s.size() && s[i + 1] == '/';
            size_t j = i + (closing ? 2 : 1), b = j;
            while (j < s.size() && nameChar(s[j]))
                ++j;
            std::string name = s.substr(b, j - b);
            if (name.empty())
                return fail("bad element name", i);
            if (closing)
            {
                if (stack.empty() || stack.back() != name)
                    return fail("mismatched </" + name + ">", i);
                if (name == "text")
                {
                    r.texts.push_back(text);
                    text.clear();
                }
                stack.pop_back();
                if (j >= s.size() || s[j] != '>')
                    return fail("bad closing tag", i);
                i = j + 1;
                continue;
            }
            if (stack.empty() && roots++ > 0)
                return fail("second root", i);
            ++r.elements[name];
            std::map<std::string, bool> attrs;
            while (true)
            {
                while (j < s.size() && (s[j] == ' ' || s[j] == '\n'))
                    ++j;
                if (j >= s.size())
                    return fail("unterminated tag", i);
                if (s[j] == '>' || (s[j] == '/' && j + 1 < s.size() && s[j + 1] == '>'))
                    break;
                size_t ab = j;
                while (j < s.size() && nameChar(s[j]))
                    ++j;
                std::string an = s.substr(ab, j - ab);
                if (an.empty() || j + 1 >= s.size() || s[j] != '=' || (s[j + 1] != '"' && s[j + 1] != '\''))
                    return fail("bad attribute", j);
                if (attrs[an])
                    return fail("duplicate attribute " + an, j);
                attrs[an] = true;
                char q = s[j + 1];
                j += 2;
                while (j < s.size() && s[j] != q)
                {
                    if (s[j] == '<')
                        return fail("'<' in attribute", j);
                    if (s[j] == '&' && !validReference(s, j))
                        return fail("bad reference in attribute", j);
                    ++j;
                }
                if (j >= s.size())
                    return fail("unterminated attribute", ab);
                ++j;
            }
            if (s[j] == '/')
                j += 2;
            else
            {
                stack.push_back(name);
                ++j;
            }
            i = j;
        }
        if (!stack.empty())
            return fail("unclosed <" + stack.back() + ">", s.size());
        if (roots != 1)
            return fail("no root", 0);
        r.ok = true;
        return r;
    }
}
