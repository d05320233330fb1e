<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/m2t/common/text.xsl - the target-neutral text kit every text stage
  includes (xslt/m2t/<target>/main.xsl): lines, banners, file entries,
  include guards, library paths; with ../../common/literals.xsl (string
  literals). A helper two targets need lives here, once.

  Reads:   elements of any PSM (fp:what, fp:doc-of, fp:library-dir read
           only attributes and a *:doc child).
  Writes:  strings, and fs:file elements (urn:robomda:fileset:1).
  Reads:   licenses.xml beside it (the notices of known licenses).
  Params:  model-dir-from-output (xs:string, default "."): the model file's
           folder relative to the output folder, '/'-separated; used only
           for relative library paths.
           maintainer-name, license, copyright-year (xs:string, default
           ""): the copyright notice every banner opens with (none without
           a maintainer).
  Errors:  none.
    fp:lines($lines)       the lines joined with "\n", plus a final "\n"
    fp:indent($n, $lines)  each non-empty line prefixed with $n spaces
    fp:fit($n, $head, $rest)  a statement on one line of at most 100 columns, else
                           broken after $head, its arguments packed on lines
    fp:cmake-warnings()    the CMake option ROBOMDA_WARNINGS (-Wall -Wextra -Wpedantic)
    fp:cmake-call($n, $head, $items)  a CMake command on one line of at most 100
                           columns, else an item a line
    fp:banner($prefix, $stylesheet, $what, $user)  the first lines of every
                           file: its copyright notice, what made it and
                           whether to edit it
    f:copyright-notice($prefix)  "Copyright YEAR MAINTAINER" and the license's notice
    f:copyright-checkable()  whether that notice is one ament_copyright accepts
    fp:file($path, $mode, $stylesheet, $text)  one fs:file
    fp:guard($dir, $name)  the include guard of $dir/$name.hpp
    fp:path-guard($path)   the include guard of header $path (under include/)
    fp:what($e)            "component 'X' of model 'M'" ($e has @name, its
                           parent @model-name)
    fp:doc-of($e, $fallback)  the element's doc text, else $fallback
    fp:clean-path($p)      a path with "/" separators, no "." or empty steps
    fp:host-lines($host)   a host's name, address, resources and buses, a line each
    fp:library-dir($lib)   the CMake default of an atomic-code library's
                           folder: as is when absolute, else relative to
                           the package (${CMAKE_CURRENT_SOURCE_DIR})
-->
<xsl:stylesheet version="3.0"
    xmlns:xsl="http://www.w3.org/1999/XSL/Transform"
    xmlns:xs="http://www.w3.org/2001/XMLSchema"
    xmlns:fs="urn:robomda:fileset:1"
    xmlns:f="urn:robomda:xslt:function"
    xmlns:fp="urn:robomda:xslt:function:private"
    exclude-result-prefixes="#all">

  <xsl:include href="../../common/literals.xsl"/>

  <xsl:param name="model-dir-from-output" as="xs:string" select="'.'">
    <!-- directory of the model file relative to the output folder, '/'-separated; used only for relative library paths -->
  </xsl:param>

  <xsl:param name="maintainer-name" as="xs:string" select="''">
    <!-- the maintainer's name; empty: a placeholder -->
  </xsl:param>
  <xsl:param name="license" as="xs:string" select="''">
    <!-- the license (an SPDX name such as Apache-2.0); empty: TODO -->
  </xsl:param>

  <xsl:param name="copyright-year" as="xs:string" select="''">
    <!-- the year of the copyright notices (YYYY); empty: notices without a year -->
  </xsl:param>

  <xsl:variable name="fp:license-notices" as="element(license)*" select="doc('licenses.xml')/licenses/license"/>

  <!-- the copyright notice a generated source file opens with, each line
       after $prefix ("// ", "# "), then an empty line: "Copyright YEAR
       MAINTAINER" and the license's own notice (licenses.xml), else its
       SPDX identifier; none without a maintainer -->
  <xsl:function name="f:copyright-notice" as="xs:string*">
    <xsl:param name="prefix" as="xs:string"/>
    <xsl:variable name="name" as="xs:string" select="normalize-space($maintainer-name)"/>
    <xsl:variable name="notice" as="xs:string*" select="
        tokenize($fp:license-notices[@spdx eq normalize-space($license)], '&#10;'),
        if (normalize-space($license) = $fp:license-notices/@spdx or normalize-space($license) eq '') then ()
        else 'SPDX-License-Identifier: ' || normalize-space($license)"/>
    <xsl:if test="$name ne ''">
      <xsl:sequence select="(string-join(('Copyright', normalize-space($copyright-year)[. ne ''], $name), ' '),
                             if (exists($notice)) then ('', $notice) else ())
                            ! (if (. eq '') then replace($prefix, '\s+$', '') else $prefix || .), ''"/>
    </xsl:if>
  </xsl:function>

  <!-- true when f:copyright-notice writes what ament_copyright accepts: a
       maintainer, a year and a license whose notice licenses.xml has -->
  <xsl:function name="f:copyright-checkable" as="xs:boolean">
    <xsl:sequence select="normalize-space($maintainer-name) ne '' and matches($copyright-year, '^\s*[0-9]{4}\s*$')
                          and normalize-space($license) = $fp:license-notices/@spdx"/>
  </xsl:function>

  <xsl:function name="fp:lines" as="xs:string">
    <xsl:param name="lines" as="xs:string*"/>
    <xsl:sequence select="concat(string-join($lines, '&#10;'), '&#10;')"/>
  </xsl:function>

  <!-- a statement $head$rest at $indent columns, in lines of at most 100
       columns (ROS 2's linters) where it can: one line when it fits, else
       broken after $head (which ends with an opening parenthesis), $rest on
       the next line 2 further in, or, when that is still too long, its
       arguments (apart at the commas outside parentheses, braces and
       strings) packed onto as few such lines as fit -->
  <xsl:function name="fp:fit" as="xs:string+">
    <xsl:param name="indent" as="xs:integer"/>
    <xsl:param name="head" as="xs:string"/>
    <xsl:param name="rest" as="xs:string"/>
    <xsl:variable name="pad" as="xs:string" select="string-join((1 to $indent) ! ' ', '')"/>
    <xsl:sequence select="if ($indent + string-length($head) + string-length($rest) le 100) then $pad || $head || $rest
                          else if ($indent + 2 + string-length($rest) le 100) then ($pad || $head, $pad || '  ' || $rest)
                          else ($pad || $head, fp:pack($pad || '  ', fp:arguments(tokenize($rest, ', '), ()), ''))"/>
  </xsl:function>

  <!-- the arguments of a list split at each ", " ($pieces): a piece joins
       the one before while that one's parentheses, braces or quotes are
       open -->
  <xsl:function name="fp:arguments" as="xs:string*">
    <xsl:param name="pieces" as="xs:string*"/>
    <xsl:param name="done" as="xs:string*"/>
    <xsl:sequence select="
        if (empty($pieces)) then $done
        else if (exists($done) and not(fp:balanced($done[last()])))
        then fp:arguments(tail($pieces), ($done[position() lt last()], $done[last()] || ', ' || head($pieces)))
        else fp:arguments(tail($pieces), ($done, head($pieces)))"/>
  </xsl:function>

  <xsl:function name="fp:balanced" as="xs:boolean">
    <xsl:param name="text" as="xs:string"/>
    <xsl:variable name="plain" as="xs:string" select="replace($text, '\\.', '')"/>
    <xsl:sequence select="string-length(replace($plain, '[^&quot;]', '')) mod 2 eq 0
        and string-length(replace($plain, '[^(]', '')) eq string-length(replace($plain, '[^)]', ''))
        and string-length(replace($plain, '[^{]', '')) eq string-length(replace($plain, '[^}]', ''))"/>
  </xsl:function>

  <!-- $arguments on lines after $pad, as many on a line as 100 columns
       hold (one at least), each line but the last ending with a comma;
       $line: the line begun -->
  <xsl:function name="fp:pack" as="xs:string*">
    <xsl:param name="pad" as="xs:string"/>
    <xsl:param name="arguments" as="xs:string*"/>
    <xsl:param name="line" as="xs:string"/>
    <xsl:variable name="next" as="xs:string?" select="head($arguments)"/>
    <xsl:sequence select="
        if (empty($next)) then $pad || $line
        else if ($line eq '') then fp:pack($pad, tail($arguments), $next)
        else if (string-length($pad || $line || ', ' || $next) le 100) then fp:pack($pad, tail($arguments), $line || ', ' || $next)
        else ($pad || $line || ',', fp:pack($pad, tail($arguments), $next))"/>
  </xsl:function>

  <!-- the CMake option that compiles a generated package with the warnings
       its code is kept free of (-Wall -Wextra -Wpedantic; on by default) -->
  <xsl:function name="fp:cmake-warnings" as="xs:string+">
    <xsl:sequence select="
        '# the warnings the generated code is kept free of (-DROBOMDA_WARNINGS=OFF: none added)',
        'option(ROBOMDA_WARNINGS &quot;compile with -Wall -Wextra -Wpedantic&quot; ON)',
        'if(ROBOMDA_WARNINGS AND CMAKE_CXX_COMPILER_ID MATCHES &quot;GNU|Clang&quot;)',
        '  add_compile_options(-Wall -Wextra -Wpedantic)',
        'endif()'"/>
  </xsl:function>

  <!-- a CMake command $head (its name, "(" and its first words) with the
       arguments $items at $indent columns: on one line when it fits in 100
       columns, else each item on a line of its own, 2 further in -->
  <xsl:function name="fp:cmake-call" as="xs:string+">
    <xsl:param name="indent" as="xs:integer"/>
    <xsl:param name="head" as="xs:string"/>
    <xsl:param name="items" as="xs:string*"/>
    <xsl:variable name="pad" as="xs:string" select="string-join((1 to $indent) ! ' ', '')"/>
    <xsl:variable name="line" as="xs:string" select="$pad || string-join(($head, $items), ' ') || ')'"/>
    <xsl:sequence select="if (string-length($line) le 100 or empty($items)) then $line
                          else ($pad || $head, $items ! ($pad || '  ' || . || (if (position() eq last()) then ')' else '')))"/>
  </xsl:function>

  <xsl:function name="fp:indent" as="xs:string*">
    <xsl:param name="name" as="xs:integer"/>
    <xsl:param name="lines" as="xs:string*"/>
    <xsl:variable name="pad" as="xs:string" select="string-join((1 to $name) ! ' ', '')"/>
    <xsl:sequence select="$lines ! (if (. eq '') then . else concat($pad, .))"/>
  </xsl:function>

  <!-- the first lines of every file: its copyright notice (none without a
       maintainer), what made it and whether to edit it; short lines (a
       linter's 100 columns) -->
  <xsl:function name="fp:banner" as="xs:string+">
    <xsl:param name="prefix" as="xs:string"/>
    <xsl:param name="stylesheet" as="xs:string"/>
    <xsl:param name="what" as="xs:string"/>
    <xsl:param name="user" as="xs:boolean"/>
    <xsl:sequence select="f:copyright-notice($prefix),
      if ($user) then (
        concat($prefix, 'Written once by robomda (', $stylesheet, ')'),
        concat($prefix, 'for ', $what, '.'),
        concat($prefix, 'This file is yours: robomda never overwrites it (a fresh copy goes beside it as *.robomda-new).'))
      else (
        concat($prefix, 'Generated by robomda (', $stylesheet, ')'),
        concat($prefix, 'for ', $what, '.'),
        concat($prefix, 'Do not edit: this file is overwritten on every generation.'))"/>
  </xsl:function>

  <xsl:function name="fp:file" as="element(fs:file)">
    <xsl:param name="path" as="xs:string"/>
    <xsl:param name="mode" as="xs:string"/>
    <xsl:param name="stylesheet" as="xs:string"/>
    <xsl:param name="text" as="xs:string"/>
    <fs:file path="{$path}" mode="{$mode}" stylesheet="{$stylesheet}">
      <xsl:value-of select="$text"/>
    </fs:file>
  </xsl:function>

  <!-- the include guard of header $dir/$name.hpp (a path under the include
       folder; $dir may be empty): the path in capitals, each "/" "__", any
       other character not a letter or digit "_", then "_" (ROS 2's style,
       which cpplint checks) -->
  <xsl:function name="fp:guard" as="xs:string">
    <xsl:param name="dir" as="xs:string"/>
    <xsl:param name="name" as="xs:string"/>
    <xsl:sequence select="fp:path-guard(string-join(($dir[. ne ''], $name || '.hpp'), '/'))"/>
  </xsl:function>

  <xsl:function name="fp:path-guard" as="xs:string">
    <xsl:param name="path" as="xs:string"/>
    <xsl:sequence select="upper-case(replace(replace($path, '/', '//'), '[^A-Za-z0-9]', '_')) || '_'"/>
  </xsl:function>

  <xsl:function name="fp:what" as="xs:string">
    <xsl:param name="element" as="element()"/>
    <xsl:sequence select="concat('component ''', $element/@name, ''' of model ''', $element/../@model-name, '''')"/>
  </xsl:function>

  <xsl:function name="fp:doc-of" as="xs:string">
    <xsl:param name="element" as="element()"/>
    <xsl:param name="fallback" as="xs:string"/>
    <xsl:sequence select="($element/*:doc/string(), $fallback)[1]"/>
  </xsl:function>

  <xsl:function name="fp:clean-path" as="xs:string">
    <xsl:param name="item" as="xs:string"/>
    <xsl:sequence select="string-join(tokenize(translate($item, '\', '/'), '/')[position() eq 1 or . ne ''][. ne '.'], '/')"/>
  </xsl:function>

  <xsl:function name="fp:library-dir" as="xs:string">
    <xsl:param name="lib" as="element()"/>
    <xsl:variable name="base" as="xs:string" select="fp:clean-path($model-dir-from-output)"/>
    <xsl:sequence select="if (xs:boolean($lib/@absolute)) then $lib/@path
        else string-join(('${CMAKE_CURRENT_SOURCE_DIR}', $base[. ne ''], fp:clean-path($lib/@path)[. ne '']), '/')"/>
  </xsl:function>

  <!-- what the model says of a PSM host (seed 002): name, address,
       resources, and its <bus> children (o:host, r:host) -->
  <xsl:function name="fp:host-lines" as="xs:string*">
    <xsl:param name="host" as="element()?"/>
    <xsl:for-each select="$host">
      <xsl:sequence select="
          'Host ''' || @name || ''' (hostname ' || @hostname || ', address ' || @address || '): '
          || string-join((@cores ! (. || ' cores'), @memory ! (. || ' MiB memory'),
                          if (@real-time = 'true') then 'real-time kernel' else 'no real-time kernel declared'), ', '),
          *:bus ! ('bus ''' || @name || ''' (' || string-join((@kind[. ne ''], @bandwidth ! (. || ' Mbit/s')), ', ') || ') to ' || @to)"/>
    </xsl:for-each>
  </xsl:function>
</xsl:stylesheet>
