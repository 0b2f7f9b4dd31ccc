/*---------------------------------------------------------------------------*\
Application
    foamDictionaryServer

Description
    OpenFOAM's foamDictionary for many requests in one process: the Python
    tools' dictionary reads and edits (flightedDryer.foamDictionary) without
    starting an OpenFOAM program per entry. A case set-up asks for about a
    hundred entries; each foamDictionary process costs about 12 ms of CPU to
    start, the request here well under a millisecond.

    A request on stdin is a count of arguments, then each argument as its
    byte length and its bytes:

        N\n  len\n bytes  len\n bytes ...

    The first argument is the folder the request is made from, the last the
    dictionary file; between them foamDictionary's options, of which these are
    served: -entry NAME with -value, -keywords, -set VALUE, -add VALUE or
    -remove; -keywords alone. The answer on stdout is the exit code
    foamDictionary would give, then what it would print on stdout and on
    stderr, each as its byte length and its bytes:

        rc\n  len\n stdout  len\n stderr

    Each request reads the file afresh, as a foamDictionary run would (#include
    and $variables expanded, the header kept), and a changed dictionary is
    written as foamDictionary writes it (banner, divider, entries, end divider),
    into a temporary file beside it that then replaces it: a killed server
    leaves the old file or the new one, never half of one. Errors are answered,
    not fatal: the server ends at the end of its input (the client closing the
    pipe or dying); SIGINT, SIGTERM and SIGHUP are ignored, as they are meant
    for that client.

\*---------------------------------------------------------------------------*/

#include "argList.H"
#include "profiling.H"
#include "Fstream.H"
#include "StringStream.H"
#include "IOobject.H"
#include "OSspecific.H"

#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>
#include <sys/stat.h>
#include <unistd.h>

using namespace Foam;

namespace
{

// One argument of a request: its length line, then its bytes
bool readArgument(std::istream& in, std::string& arg)
{
    std::string line;
    if (!std::getline(in, line)) return false;
    std::size_t n = 0;
    try { n = std::stoul(line); } catch (...) { return false; }
    arg.assign(n, '\0');
    return n == 0 || bool(in.read(&arg[0], std::streamsize(n)));
}


void writeAnswer(FILE* out, int rc, const std::string& o, const std::string& e)
{
    std::fprintf(out, "%d\n%zu\n", rc, o.size());
    std::fwrite(o.data(), 1, o.size(), out);
    std::fprintf(out, "%zu\n", e.size());
    std::fwrite(e.data(), 1, e.size(), out);
    std::fflush(out);
}


// The enclosing dictionary of a '/'- or '.'-scoped name and the keyword in it
std::pair<word, word> splitScope(const word& scoped)
{
    auto i = scoped.rfind('/');
    if (i == string::npos) i = scoped.rfind('.');
    if (i == string::npos) return {word(), scoped};
    return {word(scoped.substr(0, i)), word(scoped.substr(i + 1))};
}


dictionary& scopeOf(dictionary& dict, const word& scope)
{
    if (scope.empty()) return dict;
    const entry* e = dict.findScoped(scope, keyType::LITERAL);
    if (!e || !e->isDict())
    {
        FatalIOErrorInFunction(dict)
            << "'" << scope << "' not found in dictionary " << dict.name()
            << " or is not a dictionary" << nl
            << "Known entries are " << dict.keys() << exit(FatalIOError);
    }
    return const_cast<dictionary&>(e->dict());
}


// Write the dictionary as foamDictionary does, into a temporary file beside
// the real one (through symbolic links), then rename it over the real one
void writeDictionary(const fileName& path, const dictionary& dict)
{
    char* resolved = ::realpath(path.c_str(), nullptr);
    const fileName real(resolved ? fileName(resolved) : path);
    std::free(resolved);
    const fileName tmp(real + ".foamDictionaryServer." + Foam::name(::getpid()));
    {
        OFstream os(tmp);
        if (!os.good())
        {
            FatalErrorInFunction << "Cannot write " << tmp << exit(FatalError);
        }
        IOobject::writeBanner(os);
        IOobject::writeDivider(os);
        dict.write(os, false);
        IOobject::writeEndDivider(os);
        if (!os.good())
        {
            Foam::rm(tmp);
            FatalErrorInFunction << "Cannot write " << tmp << exit(FatalError);
        }
    }
    struct stat st;
    if (::stat(real.c_str(), &st) == 0) ::chmod(tmp.c_str(), st.st_mode & 07777);
    if (std::rename(tmp.c_str(), real.c_str()) != 0)
    {
        Foam::rm(tmp);
        FatalErrorInFunction << "Cannot replace " << real << exit(FatalError);
    }
}


// One request: its arguments without the folder; the exit code foamDictionary
// would give, what it prints on stdout into `out`
int serve(const std::vector<std::string>& args, OStringStream& out)
{
    if (args.empty())
    {
        FatalErrorInFunction << "no dictionary file named" << exit(FatalError);
    }
    const fileName path(args.back());

    string entryName, newValue;
    bool hasEntry = false, value = false, keywords = false, remove = false,
        set = false, add = false;
    for (std::size_t i = 0; i + 1 < args.size(); ++i)
    {
        const std::string& a = args[i];
        const bool takesValue = (a == "-entry" || a == "-set" || a == "-add");
        if (takesValue && i + 2 >= args.size())
        {
            FatalErrorInFunction << "option " << a << " needs a value" << exit(FatalError);
        }
        if (a == "-entry") { entryName = args[++i]; hasEntry = true; }
        else if (a == "-set") { newValue = args[++i]; set = true; }
        else if (a == "-add") { newValue = args[++i]; add = true; }
        else if (a == "-value") value = true;
        else if (a == "-keywords") keywords = true;
        else if (a == "-remove") remove = true;
        else
        {
            FatalErrorInFunction
                << "option " << a << " is not served (served: -entry NAME with -value, "
                << "-keywords, -set VALUE, -add VALUE or -remove; -keywords)" << exit(FatalError);
        }
    }

    IFstream is(path);
    if (!is.good())
    {
        FatalErrorInFunction << "Cannot open file " << path << exit(FatalError);
    }
    dictionary dict(is, true);      // the header kept, as foamDictionary reads it

    if (!hasEntry)
    {
        if (!keywords)
        {
            FatalErrorInFunction << "-entry NAME or -keywords needed" << exit(FatalError);
        }
        for (const entry& e : dict) out << e.keyword() << endl;
        return 0;
    }

    word scoped(entryName, false);
    if (scoped.find('/') == string::npos && scoped.find(':') != string::npos)
    {
        // the older ':' scoping as '.' (foamDictionary's upgrade)
        const wordList names(fileName(scoped).components(':'));
        scoped.clear();
        for (const word& n : names) scoped += (scoped.size() ? "." : "") + n;
    }

    if (set || add)
    {
        const auto sk = splitScope(scoped);
        dictionary& d = scopeOf(dict, sk.first);
        IStringStream str(string(sk.second) + ' ' + newValue + ';');
        entry* e = entry::New(str).ptr();
        if (set) d.set(e);
        else d.add(e, false);
        writeDictionary(path, dict);
        const auto found = dict.csearchScoped(scoped, keyType::REGEX);
        if (found.found()) out << found.ref();
        return 0;
    }
    if (remove)
    {
        const auto sk = splitScope(scoped);
        scopeOf(dict, sk.first).remove(sk.second);
        writeDictionary(path, dict);
        return 0;
    }

    const auto found = dict.csearchScoped(scoped, keyType::REGEX);
    if (!found.found())
    {
        FatalIOErrorInFunction(is) << "Cannot find entry " << scoped << exit(FatalIOError);
    }
    if (keywords)
    {
        for (const entry& e : found.dict()) out << e.keyword() << endl;
    }
    else if (value)
    {
        if (found.isDict())
        {
            out << found.dict();
        }
        else if (found.ref().isStream())
        {
            const tokenList& tokens = found.ref().stream();
            forAll(tokens, i)
            {
                out << tokens[i];
                if (i < tokens.size() - 1) out << token::SPACE;
            }
            out << endl;
        }
    }
    else
    {
        out << found.ref();
    }
    return 0;
}

} // End anonymous namespace


int main(int argc, char* argv[])
{
    argList::addNote
    (
        "foamDictionary's -entry/-value/-keywords/-set/-add/-remove for a stream"
        " of requests on stdin (flightedDryer.foamDictionary's co-process)"
    );
    argList::noBanner();
    argList::noParallel();
    argList::noFunctionObjects();
    profiling::disable();
    argList args(argc, argv, false, false, false);

    FatalError.throwExceptions();
    FatalIOError.throwExceptions();

    // a signal to the process group (Ctrl-C, a sweep stopping its runs) is for
    // the tool that started the server: it answers its requests until that
    // tool closes the pipe, and a request in flight is never cut off
    std::signal(SIGINT, SIG_IGN);
    std::signal(SIGTERM, SIG_IGN);
    std::signal(SIGHUP, SIG_IGN);

    // the answers go to a private copy of stdout; what OpenFOAM prints on its
    // own (warnings) is collected per request, as foamDictionary's stdout
    FILE* answers = ::fdopen(::dup(1), "w");
    std::ostringstream printed, printedErr;
    std::cout.rdbuf(printed.rdbuf());
    std::cerr.rdbuf(printedErr.rdbuf());

    std::string line;
    while (std::getline(std::cin, line))
    {
        std::size_t n = 0;
        try { n = std::stoul(line); } catch (...) { return 1; }
        std::vector<std::string> request(n);
        for (std::string& a : request)
        {
            if (!readArgument(std::cin, a)) return 1;
        }
        printed.str(""); printedErr.str("");
        int rc = 1;
        OStringStream out;
        std::string err;
        try
        {
            if (request.empty() || ::chdir(request[0].c_str()) != 0)
            {
                FatalErrorInFunction
                    << "cannot work in " << (request.empty() ? "" : request[0])
                    << exit(FatalError);
            }
            Foam::setEnv("PWD", request[0], true);
            Foam::setEnv("FOAM_CASE", request[0], true);
            rc = serve(std::vector<std::string>(request.begin() + 1, request.end()), out);
        }
        catch (const Foam::IOerror& e)
        {
            rc = 1;     // foamDictionary's exit code for every failure
            err = "--> FOAM FATAL IO ERROR: \n" + e.message() + "\n\nfile: "
                + e.ioFileName() + " at line " + Foam::name(e.ioStartLineNumber()) + ".\n";
        }
        catch (const Foam::error& e)
        {
            rc = 1;
            err = "--> FOAM FATAL ERROR: \n" + e.message() + "\n";
        }
        std::cout.flush(); std::cerr.flush();
        writeAnswer(answers, rc, printed.str() + out.str(), printedErr.str() + err);
    }
    return 0;
}
