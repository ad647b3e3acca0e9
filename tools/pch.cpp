/// The source that builds the tools' precompiled header (pch.hpp); it defines nothing.
