<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/m2t/diagrams/diagrams-text.xsl - the PlantUML text kit of the diagram
  stage (main.xsl): labels, aliases, the opening and closing lines.

  Reads:   strings and element names of the bound PIM (urn:robomda:pim:1).
  Writes:  strings (PlantUML source lines).
  Params:  none.
  Errors:  none.
    fp:puml-label($s)       $s inside a PlantUML "quoted label": &, ", <, >,
                            ~ and % (PlantUML's preprocessor would call
                            %date(), %getenv(...) in any line) as character
                            references, \ doubled, and the
                            second of a doubled * - / (Creole bold, strike,
                            italic) as a reference, line ends as spaces; so
                            any model name shows as written
    fp:puml-quoted($s)      the same in double quotes
    fp:puml-alias($prefix, $keys)  a stable alias: $prefix, then each key
                            (xmi:ids, names) with every character but a
                            letter or digit written _<code point>_, joined by
                            "__"; one-to-one, so two elements never share an
                            alias, and the same element keeps its alias from
                            one generation to the next
    fp:puml-open($title, $stylesheet, $what)  the first lines of a diagram:
                            banner, @startuml, the shared settings, title
    fp:puml-close()         the last line
-->
<xsl:stylesheet version="3.0"
    xmlns:xsl="http://www.w3.org/1999/XSL/Transform"
    xmlns:xs="http://www.w3.org/2001/XMLSchema"
    xmlns:fp="urn:robomda:xslt:function:private"
    exclude-result-prefixes="#all">

  <xsl:function name="fp:puml-label" as="xs:string">
    <xsl:param name="s" as="xs:string?"/>
    <xsl:variable name="entities" as="xs:string" select="
        string($s) => replace('&amp;', '&amp;#38;') => replace('&quot;', '&amp;#34;')
                   => replace('&lt;', '&amp;#60;') => replace('&gt;', '&amp;#62;') => replace('~', '&amp;#126;')
                   => replace('%', '&amp;#37;')"/>
    <xsl:sequence select="
        $entities => replace('\\', '\\\\') => replace('\*\*', '*&amp;#42;') => replace('--', '-&amp;#45;')
                  => replace('//', '/&amp;#47;') => replace('[&#10;&#13;&#9;]', ' ')"/>
  </xsl:function>

  <!-- fp:puml-label in double quotes -->
  <xsl:function name="fp:puml-quoted" as="xs:string">
    <xsl:param name="s" as="xs:string?"/>
    <xsl:sequence select="'&quot;' || fp:puml-label($s) || '&quot;'"/>
  </xsl:function>

  <xsl:function name="fp:puml-alias" as="xs:string">
    <xsl:param name="prefix" as="xs:string"/>
    <xsl:param name="keys" as="xs:string*"/>
    <xsl:sequence select="string-join(($prefix, $keys ! string-join(
        string-to-codepoints(.) ! (if (matches(codepoints-to-string(.), '[A-Za-z0-9]')) then codepoints-to-string(.)
                                   else '_' || . || '_'), '')), '__')"/>
  </xsl:function>

  <xsl:function name="fp:puml-open" as="xs:string+">
    <xsl:param name="title" as="xs:string"/>
    <xsl:param name="stylesheet" as="xs:string"/>
    <xsl:param name="what" as="xs:string"/>
    <xsl:sequence select="'@startuml', fp:banner(''' ', $stylesheet, $what, false()),
        ''' Render: plantuml -tsvg FILE (robomda does it when PlantUML is installed; docs/diagrams.md)',
        'set namespaceSeparator none', 'hide empty members', 'skinparam shadowing false',
        'skinparam componentStyle uml2',
        'title ' || fp:puml-label($title)"/>
  </xsl:function>

  <xsl:function name="fp:puml-close" as="xs:string">
    <xsl:sequence select="'@enduml'"/>
  </xsl:function>
</xsl:stylesheet>
