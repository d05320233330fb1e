<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/import/stereotypes.xsl - stereotype applications and comments.

  Reads:   the normalised XMI: stereotype applications are the top-level
           elements of xmi:XMI outside the UML and XMI namespaces that carry
           a base_<Metaclass> attribute (every tool writes them so: Papyrus,
           EA, MagicDraw, Modelio).
  Writes:  pim:stereotype (with pim:tag) and pim:doc, as the decoration of
           the PIM element made from the base element (named template
           tp:decoration).
  Params:  none.
  Errors:  none. An application whose base element is not in the PIM
           (a Diagram, a plain Dependency other than a StartAfter one ...)
           is not written.

  Rules
  - @name = local name of the application element; @profile = its XML
    prefix lower-cased; @profile-uri = its namespace URI; @id = its xmi:id
    (else a synthetic robomda.* id).
  - Tags: every other attribute (not base_*, not xmi:*, not xsi:*) and every
    child element. An attribute whose space-separated tokens are all ids of
    model elements gives one tag per token with ref="true"; a child element
    with xmi:idref gives a tag with ref="true"; a child with href (into a
    library) gives its href; any other child its text. Multi-valued tags
    are repeated, in document order. Empty tags, and tags equal to their
    default in profile-defaults.xml, are not written: EA writes every
    tagged value, set or not; Papyrus only those that differ from the
    default.
-->
<xsl:stylesheet version="3.0"
    xmlns:xsl="http://www.w3.org/1999/XSL/Transform"
    xmlns:xs="http://www.w3.org/2001/XMLSchema"
    xmlns:fp="urn:robomda:xslt:function:private"
    xmlns:tp="urn:robomda:xslt:template:private"
    xmlns:mp="urn:robomda:xslt:mode:private"
    xmlns:x="urn:robomda:import:xmi"
    xmlns:pim="urn:robomda:pim:1"
    exclude-result-prefixes="#all">

  <xsl:variable name="profile-defaults" as="document-node()" select="doc('profile-defaults.xml')"/>
  <xsl:key name="fp:tag-default" match="pd:tag"
      use="../@uri || '|' || @stereotype || '|' || @name"
      xmlns:pd="urn:robomda:profile-defaults"/>

  <!-- is $value the profile default of tag $name of application $app? -->
  <xsl:function name="fp:is-default-tag" as="xs:boolean">
    <xsl:param name="app" as="element()"/>
    <xsl:param name="name" as="xs:string"/>
    <xsl:param name="value" as="xs:string"/>
    <xsl:variable name="default" as="xs:string?"
        select="key('fp:tag-default', namespace-uri($app) || '|' || local-name($app) || '|' || $name,
                    $profile-defaults)[1]/@default"/>
    <xsl:sequence select="exists($default)
        and ($default eq $value
             or ($default castable as xs:double and $value castable as xs:double
                 and xs:double($default) eq xs:double($value)))"/>
  </xsl:function>

  <!-- stereotypes and documentation of the PIM element made from $e -->
  <xsl:template name="tp:decoration" as="element()*">
    <xsl:param name="e" as="element()"/>
    <xsl:variable name="id" as="xs:string" select="fp:id($e)"/>
    <xsl:if test="exists($e/ownedComment) or exists(key('fp:decorated', $id, root($e)))">
      <xsl:apply-templates select="key('fp:stereotype-by-base', $id, root($e))" mode="mp:stereotype"/>
      <xsl:for-each select="fp:doc($e)">
        <pim:doc><xsl:value-of select="."/></pim:doc>
      </xsl:for-each>
    </xsl:if>
  </xsl:template>

  <xsl:mode name="mp:stereotype" on-no-match="deep-skip"/>

  <xsl:template match="*" mode="mp:stereotype" as="element(pim:stereotype)">
    <pim:stereotype id="{fp:id(.)}" name="{local-name()}"
        profile="{lower-case(string(prefix-from-QName(node-name(.))))}"
        profile-uri="{namespace-uri()}">
      <!-- a dialect's stereotype that stands for a robomda one (dialects.xsl) -->
      <xsl:for-each select="fp:dialect-means(.)">
        <xsl:attribute name="means" select="."/>
      </xsl:for-each>
      <xsl:variable name="app" as="element()" select="."/>
      <xsl:for-each select="@*[namespace-uri() eq ''][not(starts-with(local-name(), 'base_'))][normalize-space()]
                            [not(fp:is-default-tag($app, local-name(), string(.)))]">
        <xsl:variable name="tag" as="xs:string" select="local-name()"/>
        <xsl:variable name="tokens" as="xs:string*" select="tokenize(.)"/>
        <xsl:choose>
          <xsl:when test="exists($tokens) and (every $t in $tokens satisfies exists(fp:element(.., $t)))">
            <xsl:for-each select="$tokens">
              <pim:tag name="{$tag}" value="{fp:ref-id($app, .)}" ref="true"/>
            </xsl:for-each>
          </xsl:when>
          <xsl:otherwise>
            <pim:tag name="{local-name()}" value="{.}">
              <!-- the robomda tag it stands for (dialects.xsl) -->
              <xsl:for-each select="fp:dialect-tag-means($app, $tag)">
                <xsl:attribute name="means" select="."/>
              </xsl:for-each>
            </pim:tag>
          </xsl:otherwise>
        </xsl:choose>
      </xsl:for-each>
      <xsl:for-each select="*[namespace-uri() eq '']">
        <xsl:choose>
          <xsl:when test="@x:idref">
            <pim:tag name="{local-name()}" value="{fp:ref-id(., @x:idref)}" ref="true"/>
          </xsl:when>
          <xsl:when test="@href">
            <pim:tag name="{local-name()}" value="{@href}"/>
          </xsl:when>
          <xsl:otherwise>
            <pim:tag name="{local-name()}" value="{string(.)}"/>
          </xsl:otherwise>
        </xsl:choose>
      </xsl:for-each>
    </pim:stereotype>
  </xsl:template>
</xsl:stylesheet>
