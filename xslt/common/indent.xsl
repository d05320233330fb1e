<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/common/indent.xsl - engine-independent indentation of a result tree.

  Reads:   any document (a stage's result tree, before serialization).
  Writes:  the same document with whitespace-only text dropped from
           element-only content and replaced by a newline plus two spaces
           per level before each child and before the end tag. Elements
           with text content (mixed or simple) are copied unchanged.
  Params:  none.
  Public:  f:indent($doc) indents a document; mode m:indent (template
           parameter margin: a newline and the indentation of the node's
           own line) indents one node at that margin; template
           t:indented-content (parameters children, margin, reuse) writes the
           content of an element at that margin, its children indented
           one level deeper. The last two are for a stage that writes its
           result indented in one pass instead of building it and then
           copying it through f:indent. With reuse="true()",
           t:indented-content copies a child that is indented already
           (f:indented) as it is, with no template per node: for a stage
           that passes on most of its input, which the stage before it
           indented (bind.xsl).
  Errors:  none.

  Why: serializers indent differently (Saxon 10+ wraps long attribute
  lists, SaxonJS does not), so a stage that relied on indent="yes" would
  give different bytes on different engines. Every stage serializes with
  indent="no" and indents its result with these rules (through f:indent,
  or mode m:indent as it writes it), so SaxonC-HE, SaxonJS and Saxon-HE
  Java write the same bytes.
-->
<xsl:stylesheet version="3.0"
    xmlns:xsl="http://www.w3.org/1999/XSL/Transform"
    xmlns:xs="http://www.w3.org/2001/XMLSchema"
    xmlns:f="urn:robomda:xslt:function"
    xmlns:m="urn:robomda:xslt:mode"
    xmlns:t="urn:robomda:xslt:template"
    exclude-result-prefixes="#all">

  <xsl:mode name="m:indent" on-no-match="shallow-copy"/>

  <!-- $doc indented as described above -->
  <xsl:function name="f:indent" as="document-node()">
    <xsl:param name="doc" as="document-node()"/>
    <xsl:document>
      <xsl:for-each select="$doc/node()">
        <xsl:if test="position() gt 1">
          <xsl:text>&#10;</xsl:text>
        </xsl:if>
        <xsl:apply-templates select="." mode="m:indent">
          <xsl:with-param name="margin" select="'&#10;'"/>
        </xsl:apply-templates>
      </xsl:for-each>
    </xsl:document>
  </xsl:function>

  <!-- element-only content: one child per line -->
  <xsl:template match="*[*][not(text()[normalize-space()])]" mode="m:indent" as="element()">
    <xsl:param name="margin" as="xs:string"/>
    <xsl:copy>
      <xsl:copy-of select="@*"/>
      <xsl:call-template name="t:indented-content">
        <xsl:with-param name="children" select="* | comment() | processing-instruction()"/>
        <xsl:with-param name="margin" select="$margin"/>
      </xsl:call-template>
    </xsl:copy>
  </xsl:template>

  <!-- the content of an element at $margin: each of $children on a line of
       its own, indented one level deeper, then the line of the end tag -->
  <xsl:template name="t:indented-content" as="node()*">
    <xsl:param name="children" as="node()*"/>
    <xsl:param name="margin" as="xs:string"/>
    <xsl:param name="reuse" as="xs:boolean" select="false()"/>
    <xsl:variable name="inner" as="xs:string" select="$margin || '  '"/>
    <xsl:for-each select="$children">
      <xsl:value-of select="$inner"/>
      <xsl:choose>
        <!-- no child element (most nodes of a model): what m:indent does
             with it, a copy, without a template -->
        <xsl:when test="not(*) or ($reuse and f:indented(., $inner))">
          <xsl:copy-of select="."/>
        </xsl:when>
        <xsl:otherwise>
          <xsl:apply-templates select="." mode="m:indent">
            <xsl:with-param name="margin" select="$inner"/>
          </xsl:apply-templates>
        </xsl:otherwise>
      </xsl:choose>
    </xsl:for-each>
    <xsl:if test="exists($children)">
      <xsl:value-of select="$margin"/>
    </xsl:if>
  </xsl:template>

  <!-- true when mode m:indent at $margin makes of $node a copy of it:
       $node is indented by these rules already. The element-only elements
       are checked level by level, the text between the children first
       (most nodes that are not indented fail there, at once), then each
       child element -->
  <xsl:function name="f:indented" as="xs:boolean">
    <xsl:param name="node" as="node()"/>
    <xsl:param name="margin" as="xs:string"/>
    <xsl:variable name="children" as="node()*"
        select="if ($node instance of element() and $node/* and not($node/text()[normalize-space()]))
                then $node/(* | comment() | processing-instruction()) else ()"/>
    <xsl:variable name="texts" as="text()*" select="if (exists($children)) then $node/text() else ()"/>
    <xsl:variable name="inner" as="xs:string" select="$margin || '  '"/>
    <!-- two text nodes are never adjacent: as many texts as children plus
         one, a text first and last, alternate -->
    <xsl:sequence select="empty($children)
        or (count($texts) eq count($children) + 1
            and $node/node()[1] instance of text() and $node/node()[last()] instance of text()
            and string($texts[last()]) eq $margin
            and (every $text in $texts[position() lt last()] satisfies string($text) eq $inner)
            and (every $child in $children[. instance of element()] satisfies f:indented($child, $inner)))"/>
  </xsl:function>

  <!-- anything else (empty, text-only or mixed content): as it is -->
  <xsl:template match="*" mode="m:indent" as="element()">
    <xsl:param name="margin" as="xs:string"/>
    <xsl:copy-of select="."/>
  </xsl:template>
</xsl:stylesheet>
