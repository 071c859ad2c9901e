// HOSTILE FIXTURE macro_hidden_names (attack class 12: hides the mechanism (asm, .incbin, macros, no headers, dlsym, thread_local, threads)).
// Defines its own main() and calls _exit without ever writing the names: token pasting (ma##in), a line splice inside an identifier, digraphs (%:define, <% %>), _Pragma to silence warnings, and a (C++17-ignored) trigraph in a comment.
// The hardened grader must give this file 0 points on stage 04.
//@head
#include <cstdio>
#include <string>
#include <unistd.h>
#include <gtest/gtest.h>
//@tail

// ATTACK: none of the names a screen greps for appears as a token in the source text.
_Pragma("GCC diagnostic push")
_Pragma("GCC diagnostic ignored \"-Wpedantic\"")
%:define HOSTILE_CAT(a, b) a##b
%:define HOSTILE_ENTRY HOSTILE_CAT(ma, in)
%:define HOSTILE_LEAVE HOSTILE_CAT(_ex, it)
// a trigraph a pre-C++17 screen may mis-read: ??/
namespace <%
std::string hostileWhat(const char* prefix) <%
    std::FILE* f = std::fopen("/proc/self/cmdline", "rb");
    if (!f) return "";
    char buf[8192];
    const std::size_t n = std::fread(buf, 1, sizeof buf - 1, f);
    std::fclose(f);
    buf[n] = 0;
    const std::string p(prefix);
    for (std::size_t i = 0; i < n; i += std::string(buf + i).size() + 1)
        if (std::string(buf + i).compare(0, p.size(), p) == 0) return std::string(buf + i + p.size());
    return "";
%>
%>  // namespace
int HOSTILE_ENTRY(int argc, char** argv) <%
    const std::string out = hostileWhat("--gtest_output=json:"), name = hostileWhat("--gtest_filter=");
    if (!out.empty()) <%
        if (std::FILE* f = std::fopen(out.c_str(), "w")) <%
            std::fprintf(f, "{\"testsuites\": [{\"name\": \"%s\", \"testsuite\": [{\"name\": \"%s\"}]}]}\n",
                         name.substr(0, name.find('.')).c_str(), name.substr(name.find('.') + 1).c_str());
            std::fclose(f);
        %>
        HOSTILE_LEAVE(0);
    %>
    ::testing::InitGoogle\
Test(&argc, argv);
    return RUN_ALL_TESTS();
%>
_Pragma("GCC diagnostic pop")
